// The cubic fitted to a curve known only by evaluation (curve_fit.h): it follows the curve
// within the tolerance, and it is C2 where a C2 cubic can be made to follow it, so that later
// intersections with the edge do not take it piece by piece.
#include <gtest/gtest.h>

#include <cmath>

#include <GeomAdaptor_Curve.hxx>

#include "airshape/geometry/curve_fit.h"

namespace airshape::geometry {
namespace {

/// A curve whose curvature changes fast near t = 0, as a rib's outline round a leading edge
/// does: a parabola (x = t², z = t / 10) with a narrow bump (z += exp(-200 t²) / 50). The
/// samples the Hermite cubic needs are too uneven there for the C2 cubic through them alone.
CurveSample noseAt(double t) {
  const double a = std::exp(-200.0 * t * t);
  return {t, gp_Pnt(t * t, 0.0, 0.1 * t + 0.02 * a), gp_Vec(2.0 * t, 0.0, 0.1 - 8.0 * t * a), gp_Pnt2d()};
}

const CurveSampler kNose = [](double t, const CurveSample&, const CurveSample&) {
  return std::optional<CurveSample>(noseAt(t));
};

TEST(CurveFit, ARibsNoseIsFittedByAC2CubicThatFollowsIt) {
  const double tolerance = 1e-9;
  const Handle(Geom_BSplineCurve) curve = fittedCurve(kNose, noseAt(-1.0), noseAt(1.0), tolerance);
  ASSERT_FALSE(curve.IsNull());
  EXPECT_EQ(GeomAdaptor_Curve(curve).NbIntervals(GeomAbs_C2), 1);
  double farthest = 0.0;
  for (int i = 0; i <= 4000; ++i) {
    const double t = -1.0 + 2.0 * i / 4000.0;
    farthest = std::max(farthest, curve->Value(t).Distance(noseAt(t).point));
  }
  EXPECT_LE(farthest, 2.0 * tolerance);
  EXPECT_LT(curve->Value(-1.0).Distance(noseAt(-1.0).point), 1e-15);
  EXPECT_LT(curve->Value(1.0).Distance(noseAt(1.0).point), 1e-15);
}

}  // namespace
}  // namespace airshape::geometry
