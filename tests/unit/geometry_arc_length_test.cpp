// Arc lengths along B-splines (geometry/arc_length.h) agree with OCCT's adaptive integration.
#include <cmath>

#include <gtest/gtest.h>
#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>

#include "airshape/geometry/arc_length.h"
#include "airshape/geometry/curve_interpolation.h"

namespace airshape::geometry {
namespace {

/// A closed curve through points of an ellipse (a fuselage profile's kind of curve).
Handle(Geom_BSplineCurve) ellipse() {
  constexpr int kPoints = 40;
  std::vector<gp_Pnt> points;
  std::vector<double> parameters;
  for (int i = 0; i <= kPoints; ++i) {
    const double a = 2.0 * M_PI * i / kPoints;
    points.emplace_back(0.0, 2.0 * std::sin(a), 1.3 * std::cos(a));
    parameters.push_back(static_cast<double>(i) / kPoints);
  }
  points.back() = points.front();
  return interpolateCurve(points, parameters, 3, true);
}

/// An open curve whose speed nearly vanishes where it turns back (a cusp-like corner).
Handle(Geom_BSplineCurve) sharpTurn() {
  const std::vector<gp_Pnt> points = {gp_Pnt(0, 0, 0),       gp_Pnt(1, 0.2, 0), gp_Pnt(2, 0.0, 0),
                                      gp_Pnt(1.0, 0.001, 0), gp_Pnt(0.5, 1, 0), gp_Pnt(0, 3, 1)};
  return interpolateCurve(points, {0.0, 0.2, 0.4, 0.5, 0.7, 1.0}, 3, false);
}

void expectAgreesWithOcct(const Handle(Geom_BSplineCurve) & curve) {
  const ArcLength arc(curve);
  GeomAdaptor_Curve adaptor(curve);
  const double first = curve->FirstParameter(), last = curve->LastParameter();
  const double total = GCPnts_AbscissaPoint::Length(adaptor, first, last, 1e-12);
  EXPECT_NEAR(arc.total(), total, 1e-11 * total);
  for (int i = 0; i <= 20; ++i) {
    const double t = first + (last - first) * i / 20.0;
    EXPECT_NEAR(arc.lengthAt(t), GCPnts_AbscissaPoint::Length(adaptor, first, t, 1e-12), 1e-11 * total);
    const double length = total * i / 20.0;
    const double at = arc.parameterAt(length);
    EXPECT_NEAR(GCPnts_AbscissaPoint::Length(adaptor, first, at, 1e-12), length, 1e-11 * total) << "share " << i;
  }
  EXPECT_EQ(arc.parameterAt(-1.0), first);
  EXPECT_EQ(arc.parameterAt(2.0 * total), last);
}

TEST(ArcLength, AgreesWithOcctOnAClosedProfile) { expectAgreesWithOcct(ellipse()); }

TEST(ArcLength, AgreesWithOcctWhereTheSpeedNearlyVanishes) { expectAgreesWithOcct(sharpTurn()); }

}  // namespace
}  // namespace airshape::geometry
