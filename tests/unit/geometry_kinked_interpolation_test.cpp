// Interpolation with corners, the seam of closed lists, concatenation and piecewise-linear
// reparametrisation keep points, corners and shapes.
#include <cmath>

#include <gtest/gtest.h>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/kinked_interpolation.h"

namespace airshape::geometry {
namespace {

std::vector<gp_Pnt> closedWavyList(int count) {
  std::vector<gp_Pnt> points;
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * M_PI * i / (count - 1);
    points.emplace_back(0.0, std::sin(a) * (1.0 + 0.1 * std::cos(3 * a)), std::cos(a));
  }
  points.back() = points.front();
  return points;
}

double turn(const Geom_BSplineCurve& curve, double t) {
  return curve.DN(std::max(t - 1e-7, curve.FirstParameter()), 1)
      .Angle(curve.DN(std::min(t + 1e-7, curve.LastParameter()), 1));
}

/// Whether t is a knot of full multiplicity (the curve may turn there).
bool isCornerKnot(const Geom_BSplineCurve& curve, double t) {
  for (int i = 1; i <= curve.NbKnots(); ++i)
    if (std::abs(curve.Knot(i) - t) < 1e-12) return curve.Multiplicity(i) >= curve.Degree();
  return false;
}

TEST(KinkedInterpolation, CornersWhereAskedAndASmoothSeamOtherwise) {
  const auto points = closedWavyList(17);
  const auto parameters = chordParameters(points, 0.5);
  const std::vector<int> kinks = {4, 11};
  const auto curve = interpolateWithCorners(points, parameters, kinks, true);
  EXPECT_NEAR(curve->FirstParameter(), 0.0, 1e-15);
  EXPECT_NEAR(curve->LastParameter(), 1.0, 1e-15);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_LT(curve->Value(parameters[i]).Distance(points[i]), 1e-10) << i;
  for (int k : kinks) EXPECT_TRUE(isCornerKnot(*curve, parameters[static_cast<std::size_t>(k)])) << k;
  // The seam lies inside the run from the last corner to the first: smooth there.
  EXPECT_LT(curve->DN(0.0, 1).Angle(curve->DN(1.0, 1)), 1e-6);
  EXPECT_LT(turn(*curve, parameters[8]), 1e-5);
}

TEST(KinkedInterpolation, ACornerAtTheSeamMakesItSharp) {
  const auto points = closedWavyList(13);
  const auto parameters = chordParameters(points, 0.5);
  const auto curve = interpolateWithCorners(points, parameters, {0}, true);
  EXPECT_FALSE(curve->IsPeriodic());
  EXPECT_LT(curve->StartPoint().Distance(curve->EndPoint()), 1e-12);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_LT(curve->Value(parameters[i]).Distance(points[i]), 1e-10) << i;
}

TEST(KinkedInterpolation, PiecewiseLinearReparametrisationMovesParametersNotPoints) {
  const auto points = closedWavyList(13);
  const auto parameters = chordParameters(points, 0.5);
  const auto curve = interpolateWithCorners(points, parameters, {}, true);
  // Point 3 moves to parameter 0.5; the others follow linearly between 0, 0.5 and 1.
  auto newParameter = [&](double t) {
    return t < parameters[3] ? 0.5 * t / parameters[3] : 0.5 + 0.5 * (t - parameters[3]) / (1.0 - parameters[3]);
  };
  std::vector<double> to;
  for (double t : parameters) to.push_back(newParameter(t));
  const auto moved = reparametrisePiecewiseLinearly(*curve, parameters, to);
  EXPECT_LT(moved->Value(0.5).Distance(points[3]), 1e-10);
  for (double s : {0.1, 0.3, 0.7, 0.95}) {
    const double t = s < 0.5 ? s / 0.5 * parameters[3] : parameters[3] + (s - 0.5) / 0.5 * (1.0 - parameters[3]);
    EXPECT_LT(moved->Value(s).Distance(curve->Value(t)), 1e-10) << s;
  }
  // Every point's new parameter is a knot: of full multiplicity where the map bends
  // (point 3), simple where it runs straight on.
  for (std::size_t i = 1; i + 1 < to.size(); ++i) {
    int index = 0;
    for (int k = 1; k <= moved->NbKnots(); ++k)
      if (std::abs(moved->Knot(k) - to[i]) < 1e-12) index = k;
    ASSERT_NE(index, 0) << i;
    EXPECT_EQ(moved->Multiplicity(index), i == 3 ? moved->Degree() : 1) << i;
  }
}

TEST(KinkedInterpolation, AParameterMapMustIncrease) {
  const auto points = closedWavyList(13);
  const auto parameters = chordParameters(points, 0.5);
  const auto curve = interpolateWithCorners(points, parameters, {}, true);
  std::vector<double> to = parameters;
  std::swap(to[2], to[3]);
  EXPECT_THROW(reparametrisePiecewiseLinearly(*curve, parameters, to), Error);
}

}  // namespace
}  // namespace airshape::geometry
