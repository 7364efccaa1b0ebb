// Brent's search for the smallest value: as exact as the golden sections it replaced where the
// minimum is a smooth one, in far fewer evaluations, and still right where parabolas mislead.
#include <cmath>

#include <gtest/gtest.h>

#include "airshape/geometry/smallest_value.h"

namespace airshape::geometry {
namespace {

TEST(ArgumentOfMinimum, FindsTheVertexOfAParabolaToTheToleranceInAFewSteps) {
  int evaluations = 0;
  const double found = argumentOfMinimum(
      [&](double x) {
        ++evaluations;
        return 3.0 * (x - 0.3141592653589793) * (x - 0.3141592653589793);
      },
      0.0, 1.0, 1e-12);
  EXPECT_NEAR(found, 0.3141592653589793, 1e-12);
  EXPECT_LT(evaluations, 20);  // golden sections alone: 58
}

TEST(ArgumentOfMinimum, FindsAFlatMinimumAsCloselyAsRoundingTellsItsValues) {
  // Above zero the values near the minimum agree to rounding within about the square root of
  // the machine's precision of it: no search can tell those points apart.
  const double found = argumentOfMinimum(
      [](double x) { return 3.0 * (x - 0.3141592653589793) * (x - 0.3141592653589793) + 2.0; }, 0.0, 1.0, 1e-12);
  EXPECT_NEAR(found, 0.3141592653589793, 1e-7);
}

TEST(ArgumentOfMinimum, FindsTheZeroOfASquaredDistanceToRounding) {
  // The squared distance to a line whose point moves non-linearly: what etaOf minimises for a
  // point on the chord surface.
  const double target = 0.7236067977499789;
  const double found = argumentOfMinimum(
      [&](double eta) {
        const double moved = std::sin(eta) - std::sin(target);
        return moved * moved * (1.0 + eta * eta);
      },
      0.0, 1.0, 1e-12);
  EXPECT_NEAR(found, target, 1e-11);
}

TEST(ArgumentOfMinimum, FindsACornerWhereParabolasDoNotFit) {
  // |x - c| has a corner at its minimum: the parabolas are rejected, golden sections close in.
  const double found = argumentOfMinimum([](double x) { return std::abs(x - 0.6); }, 0.0, 1.0, 1e-12);
  EXPECT_NEAR(found, 0.6, 1e-11);
}

TEST(ArgumentOfMinimum, FindsAMinimumAtAnEndOfTheInterval) {
  EXPECT_NEAR(argumentOfMinimum([](double x) { return x; }, 0.0, 1.0, 1e-12), 0.0, 1e-11);
  EXPECT_NEAR(argumentOfMinimum([](double x) { return -x * x; }, 0.0, 1.0, 1e-12), 1.0, 1e-11);
}

}  // namespace
}  // namespace airshape::geometry
