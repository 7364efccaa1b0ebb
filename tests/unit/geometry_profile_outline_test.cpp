// A profile's points must outline some area without crossing themselves. A polygon crosses
// itself where two of its sides cross inside both; sides that touch within the tolerance
// and sides of no length do not count; the closing side of the outline does.
#include <cmath>

#include <gtest/gtest.h>

#include <gp_Pnt.hxx>
#include <gp_Vec2d.hxx>

#include "airshape/error.h"
#include "airshape/geometry/profile_outline.h"

namespace airshape::geometry {
namespace {

TEST(PolygonCrossing, AConvexOutlineDoesNotCross) {
  EXPECT_FALSE(polygonCrossing({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1e-9));
  // An airfoil-like outline, trailing edge given twice (a side of no length).
  EXPECT_FALSE(polygonCrossing({{1, 0}, {0.5, 0.06}, {0, 0}, {0.5, -0.05}, {1, 0}}, 1e-9));
}

TEST(PolygonCrossing, ABowTieCrossesBetweenItsLongSides) {
  const auto crossing = polygonCrossing({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 1e-9);
  ASSERT_TRUE(crossing);
  EXPECT_EQ(crossing->first, 0u);   // side (0,0)-(1,1) ...
  EXPECT_EQ(crossing->second, 2u);  // ... crosses side (1,0)-(0,1)
}

TEST(PolygonCrossing, TheClosingSideCounts) {
  // Corners in order but for the last, whose closing side back to the first cuts through.
  const auto crossing = polygonCrossing({{0, 0}, {2, 0}, {2, 2}, {1, -1}}, 1e-9);
  ASSERT_TRUE(crossing);
  EXPECT_EQ(crossing->first, 0u);
  EXPECT_EQ(crossing->second, 2u);
}

TEST(PolygonCrossing, SidesThatOnlyTouchDoNotCross) {
  // A corner resting on another side, and two sides along one line.
  EXPECT_FALSE(polygonCrossing({{0, 0}, {2, 0}, {1, 1}, {1, 0}, {0.5, 1}}, 1e-9));
  EXPECT_FALSE(polygonCrossing({{0, 0}, {2, 0}, {3, 0}, {1, 0}, {1, 1}}, 1e-9));
}

TEST(PolygonCrossing, ACrossingWithinTheToleranceIsATouch) {
  // An airfoil whose trailing-edge ends lie 2e-17 apart, the upper side starting just below
  // the lower side's end: its first and last sides cross, by far less than the tolerance.
  const std::vector<gp_Pnt2d> airfoil = {{1, -1e-17}, {0.998, 3e-4}, {0, 0}, {0.998, -1e-4}, {1, 1e-17}};
  EXPECT_TRUE(polygonCrossing(airfoil, 0.0));
  EXPECT_FALSE(polygonCrossing(airfoil, 1e-9));
}

/// The message requireProfileOutline throws for these corners, or "" when it throws none.
std::string outlineError(const std::vector<gp_Pnt2d>& corners, const std::vector<int>& placeInFile = {}) {
  try {
    requireProfileOutline(corners, 1e-7, placeInFile, "/profile/pointList");
  } catch (const Error& error) {
    EXPECT_EQ(error.cpacsPath(), "/profile/pointList");
    return error.message();
  }
  return "";
}

TEST(ProfileOutline, PointsOnALineEncloseNoArea) {
  EXPECT_EQ(outlineError({{1, 0}, {0.5, 0}, {0, 0}, {0.5, 0}, {1, 0}}),
            "the points enclose no area (they lie on a line)");
  EXPECT_EQ(outlineError({{1, 0}, {0.5, 0.05}, {0, 0}, {0.5, -0.05}, {1, 0}}), "");
  EXPECT_EQ(outlineError({{1, 0}, {0, 0}}), "");  // too few points: the caller's error
}

TEST(ProfileOutline, ACrossingNamesTheSidesByTheirPlaceInTheFile) {
  const std::vector<gp_Pnt2d> bowTie = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_EQ(outlineError(bowTie),
            "the points' outline crosses itself (its sides from point 1 and from point 3 cross by 0.5 of the "
            "profile's size, more than the tolerated 1e-05): points out of order?");
  // The same corners read from a list in which duplicates were dropped.
  EXPECT_EQ(outlineError(bowTie, {0, 2, 3, 5}),
            "the points' outline crosses itself (its sides from point 1 and from point 4 cross by 0.5 of the "
            "profile's size, more than the tolerated 1e-05): points out of order?");
}

/// A symmetric airfoil's outline, trailing edge to leading edge along the upper side and back
/// along the lower side, with points crowding at the leading edge as optimisers write them.
std::vector<gp_Pnt2d> airfoilOutline() {
  std::vector<gp_Pnt2d> corners;
  const auto thickness = [](double x) { return 0.06 * std::sqrt(x) * (1 - x); };
  for (int i = 0; i <= 40; ++i) {
    const double x = std::pow(1.0 - i / 40.0, 2);
    corners.emplace_back(x, thickness(x));
  }
  for (int i = 39; i >= 0; --i) corners.emplace_back(corners[i].X(), -corners[i].Y());
  return corners;
}

TEST(ProfileOutline, ACrossingWithinTheToleranceIsLoftedWithAWarning) {
  // At the leading edge the last upper point lies below the first lower one, by a micrometre on
  // a chord of one metre: the outline zig-zags and crosses itself by a few millionths.
  std::vector<gp_Pnt2d> zigZag = airfoilOutline();
  zigZag[39] = gp_Pnt2d(2e-6, 1e-6);
  zigZag[40] = gp_Pnt2d(0, 0);
  zigZag[41] = gp_Pnt2d(1e-6, 2e-6);
  const auto slight = polygonCrossing(zigZag, 1e-9);
  ASSERT_TRUE(slight);
  EXPECT_LT(crossingDepth(zigZag, *slight), kToleratedCrossing);
  const std::optional<std::string> warning = requireProfileOutline(zigZag, 1e-7, {}, "/profile/pointList");
  ASSERT_TRUE(warning);
  EXPECT_NE(warning->find("less than the tolerated 0.001 for a zig-zag"), std::string::npos) << *warning;
  EXPECT_NE(warning->find("lofted as given"), std::string::npos) << *warning;
  EXPECT_FALSE(requireProfileOutline(airfoilOutline(), 1e-7, {}, "/profile/pointList"));
  // Points of the middle of the upper side swapped: a crossing of a tenth of the chord stays an error.
  std::vector<gp_Pnt2d> outOfOrder = airfoilOutline();
  std::swap(outOfOrder[10], outOfOrder[20]);
  EXPECT_NE(outlineError(outOfOrder).find("more than the tolerated 1e-05"), std::string::npos)
      << outlineError(outOfOrder);
}

TEST(ProfileOutline, AZigZagsLoopIsReplacedByThePointWhereItsSidesCross) {
  std::vector<gp_Pnt2d> zigZag = airfoilOutline();
  zigZag[39] = gp_Pnt2d(2e-4, 1e-4);
  zigZag[40] = gp_Pnt2d(0, 0);
  zigZag[41] = gp_Pnt2d(1e-4, 2e-4);
  const std::vector<ZigZag> found = zigZags(zigZag, 1e-9);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_LE(found[0].lastSide - found[0].firstSide, kZigZagReach);
  std::vector<gp_Pnt> points;
  for (const gp_Pnt2d& corner : zigZag) points.emplace_back(corner.X(), 0.0, corner.Y());
  const std::vector<gp_Pnt> kept = withoutZigZags(points, found);
  EXPECT_EQ(kept.size(), points.size() - (found[0].lastSide - found[0].firstSide) + 1);
  std::vector<gp_Pnt2d> untangled;
  for (const gp_Pnt& point : kept) untangled.emplace_back(point.X(), point.Z());
  EXPECT_FALSE(polygonCrossing(untangled, 1e-9));
  // The new corner lies on both crossing sides.
  const gp_Pnt& crossing = kept[found[0].firstSide + 1];
  for (std::size_t side : {found[0].firstSide, found[0].lastSide}) {
    const gp_Vec2d along(zigZag[side], zigZag[side + 1]);
    EXPECT_NEAR(along.Crossed(gp_Vec2d(zigZag[side], gp_Pnt2d(crossing.X(), crossing.Z()))) / along.Magnitude(), 0.0,
                1e-15);
  }
  // The airfoil without a zig-zag has none; a crossing deeper than a zig-zag may be is none either.
  EXPECT_TRUE(zigZags(airfoilOutline(), 1e-9).empty());
  std::vector<gp_Pnt2d> deep = airfoilOutline();
  std::swap(deep[39], deep[41]);  // the points on either side of the leading edge swapped
  const auto deepCrossing = polygonCrossing(deep, 1e-9);
  ASSERT_TRUE(deepCrossing);
  EXPECT_GT(crossingDepth(deep, *deepCrossing), kToleratedZigZag * 1.1);  // the outline is about 1 across
  EXPECT_TRUE(zigZags(deep, 1e-9).empty());
}

}  // namespace
}  // namespace airshape::geometry
