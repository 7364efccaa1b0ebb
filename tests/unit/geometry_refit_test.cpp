// The uniform re-fit of profile curves: power-of-two spans, ends and corners kept, a smooth
// seam stays smooth, the shape and parametrisation hardly move.
#include <cmath>

#include <gtest/gtest.h>

#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/uniform_refit.h"

namespace airshape::geometry {
namespace {

std::vector<gp_Pnt> circlePoints(int intervals) {
  std::vector<gp_Pnt> points;
  for (int i = 0; i <= intervals; ++i) {
    const double a = 2.0 * M_PI * i / intervals;
    points.emplace_back(0.0, std::sin(a), std::cos(a));
  }
  points.back() = points.front();
  return points;
}

int interiorSpans(const Geom_BSplineCurve& curve) { return curve.NbKnots() - 1; }

TEST(UniformRefit, ClosedCurvesKeepTheirShapeAndAreC2AtTheSeam) {
  for (int intervals : {12, 16, 40}) {
    const auto points = circlePoints(intervals);
    const auto parameters = chordParameters(points, 0.5);
    const auto original = interpolateCurve(points, parameters, 3, true);
    const auto refit = refitOnUniformSpans(*original, parameters);
    // The largest power of two not above the point intervals, at least 8.
    const int expected = std::max(8, 1 << static_cast<int>(std::floor(std::log2(intervals))));
    EXPECT_EQ(interiorSpans(*refit), expected) << intervals;
    EXPECT_EQ(refit->Degree(), 3);
    EXPECT_FALSE(refit->IsPeriodic());
    EXPECT_LT(refit->StartPoint().Distance(points.front()), 1e-12);
    EXPECT_LT(refit->EndPoint().Distance(points.front()), 1e-12);
    for (int order = 1; order <= 2; ++order)
      EXPECT_LT((refit->DN(0.0, order) - refit->DN(1.0, order)).Magnitude(), 1e-8) << intervals;
    for (int i = 0; i <= 200; ++i) {  // same parametrisation, nearly the same points
      const double t = i / 200.0;
      EXPECT_LT(refit->Value(t).Distance(original->Value(t)), 2e-3) << intervals << " at " << t;
    }
  }
}

TEST(UniformRefit, CornersStayCorners) {
  // A square with a corner at each point: interpolated piece by piece, corners as knots.
  const std::vector<gp_Pnt> points = {gp_Pnt(0, 0, 0), gp_Pnt(0, 1, 0), gp_Pnt(0, 1, 1), gp_Pnt(0, 0, 1),
                                      gp_Pnt(0, 0, 0.5)};
  const auto parameters = chordParameters(points, 1.0);
  const auto original = interpolateCurve(points, parameters, 3, false, {1, 2, 3});
  const auto refit = refitOnUniformSpans(*original, parameters);
  for (int k : {1, 2, 3}) {
    const double t = parameters[static_cast<std::size_t>(k)];
    EXPECT_LT(refit->Value(t).Distance(points[static_cast<std::size_t>(k)]), 1e-10);
    EXPECT_GT(refit->DN(t - 1e-6, 1).Angle(refit->DN(t + 1e-6, 1)), M_PI / 4);
  }
}

}  // namespace
}  // namespace airshape::geometry
