// Piecewise Chebyshev approximation of curves given as functions: polynomials come out
// exactly, smooth curves within the tolerance, and the ends are kept.
#include <cmath>

#include <gtest/gtest.h>

#include "airshape/geometry/chebyshev_approximation.h"

namespace airshape::geometry {
namespace {

double largestDeviation(const Geom_BSplineCurve& curve, const std::function<gp_Pnt(double)>& f, double a, double b) {
  double largest = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double t = a + (b - a) * i / 1000.0;
    largest = std::max(largest, curve.Value(t).Distance(f(t)));
  }
  return largest;
}

TEST(ChebyshevApproximation, APolynomialOfTheDegreeIsOnePieceAndExact) {
  const auto cubic = [](double t) { return gp_Pnt(t, 2 * t * t * t - t, 0.5 - t * t); };
  const auto curve = approximateByChebyshevPieces(cubic, -1.0, 2.0, {3, 1e-9, 10});
  EXPECT_EQ(curve->NbKnots(), 2);
  EXPECT_EQ(curve->Degree(), 3);
  EXPECT_LT(largestDeviation(*curve, cubic, -1.0, 2.0), 1e-12);
}

TEST(ChebyshevApproximation, ASmoothCurveIsSplitUntilItIsCloseEnough) {
  const auto airfoilLike = [](double t) {
    const double x = t * t;
    return gp_Pnt(x, 0.0, 0.6 * (0.2969 * std::sqrt(x) - 0.126 * x - 0.3516 * x * x + 0.2843 * x * x * x));
  };
  for (double tolerance : {1e-4, 1e-6}) {
    const auto curve = approximateByChebyshevPieces(airfoilLike, 0.0, 1.0, {4, tolerance, 10});
    EXPECT_GT(curve->NbKnots(), 2);
    // The tail sum estimates the error and the C1 joins move points near them: of the order
    // of the tolerance, not bounded by it.
    EXPECT_LT(largestDeviation(*curve, airfoilLike, 0.0, 1.0), 5 * tolerance);
    EXPECT_LT(curve->StartPoint().Distance(airfoilLike(0.0)), 1e-15);
    EXPECT_LT(curve->EndPoint().Distance(airfoilLike(1.0)), 1e-15);
    EXPECT_GE(curve->Continuity(), GeomAbs_C1);
  }
}

TEST(ChebyshevApproximation, EachCoordinateIsJudgedOnItsOwn) {
  // T_5 in y and z with coefficient a: each coordinate's tail is a, their vector's a·√2.
  const double tolerance = 1e-6, a = 0.8 * tolerance;
  const auto t5 = [a](double t) { return a * (16 * std::pow(t, 5) - 20 * std::pow(t, 3) + 5 * t); };
  const auto curve =
      approximateByChebyshevPieces([&](double t) { return gp_Pnt(t, t5(t), t5(t)); }, -1.0, 1.0, {3, tolerance, 10});
  EXPECT_EQ(curve->NbKnots(), 2);  // one piece: 0.8 of the tolerance in y and in z
  const auto wider = approximateByChebyshevPieces([&](double t) { return gp_Pnt(t, 1.3 * t5(t), 0.0); }, -1.0, 1.0,
                                                  {3, tolerance, 10});
  EXPECT_GT(wider->NbKnots(), 2);  // 1.04 of it in y alone
}

TEST(ChebyshevApproximation, TheDepthLimitStopsSplitting) {
  const auto kinked = [](double t) { return gp_Pnt(t, std::abs(t - 0.3), 0.0); };
  const auto curve = approximateByChebyshevPieces(kinked, 0.0, 1.0, {3, 1e-12, 4});
  EXPECT_LE(curve->NbKnots(), 9);  // at most 2^(4−1) pieces
}

}  // namespace
}  // namespace airshape::geometry
