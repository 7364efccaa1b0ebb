// A cell's prism answers inside or outside in closed form: checked against prisms whose inside is
// known independently (a polygon test in the plane across straight lines, the projection from the
// apex of lines that meet), and it declines to answer where a point lies on a side.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "airshape/geometry/ruled_prism.h"

namespace airshape::geometry {
namespace {

/// Whether (x, y) lies inside the closed polygon, by the parity of edges crossed to the right.
bool insidePolygon(const std::vector<gp_Pnt>& polygon, double x, double y) {
  bool inside = false;
  for (std::size_t k = 0, previous = polygon.size() - 1; k < polygon.size(); previous = k++) {
    const gp_Pnt& a = polygon[k];
    const gp_Pnt& b = polygon[previous];
    if ((a.Y() > y) != (b.Y() > y) && x < a.X() + (y - a.Y()) * (b.X() - a.X()) / (b.Y() - a.Y())) inside = !inside;
  }
  return inside;
}

/// Points on a grid that avoids the outlines' coordinates, from -1.05 to 2.05 in each direction.
std::vector<gp_Pnt> gridPoints(double zFrom, double zTo) {
  std::vector<gp_Pnt> points;
  for (int i = 0; i <= 31; ++i)
    for (int j = 0; j <= 31; ++j)
      for (int k = 0; k <= 4; ++k)
        points.emplace_back(-1.05 + 0.1 * i + 0.0013 * j, -1.05 + 0.1 * j + 0.0007 * i,
                            zFrom + (zTo - zFrom) * k / 4.0);
  return points;
}

TEST(RuledPrism, AnLShapedOutlineAlongParallelLinesIsInsideWhereThePolygonIs) {
  const std::vector<gp_Pnt> outline{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  const std::vector<gp_Vec> up(outline.size(), gp_Vec(0, 0, 1));
  const RuledPrism prism(outline, up, 3.0);
  int inside = 0;
  for (const gp_Pnt& point : gridPoints(-2.9, 2.9)) {
    const std::optional<bool> answer = prism.contains(point);
    ASSERT_TRUE(answer.has_value()) << point.X() << " " << point.Y() << " " << point.Z();
    EXPECT_EQ(*answer, insidePolygon(outline, point.X(), point.Y())) << point.X() << " " << point.Y();
    inside += *answer ? 1 : 0;
  }
  EXPECT_GT(inside, 500);  // the grid does reach inside
}

TEST(RuledPrism, LinesLeaningAlikeKeepTheOutlineAlongTheirDirection) {
  const std::vector<gp_Pnt> outline{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  const gp_Vec lean(0.4, -0.3, 1.0);
  const RuledPrism prism(outline, std::vector<gp_Vec>(outline.size(), lean), 3.0);
  for (const gp_Pnt& point : gridPoints(-2.5, 2.5)) {
    // Back along the lines to the outline's plane.
    const double t = point.Z() / lean.Z();
    const std::optional<bool> answer = prism.contains(point);
    ASSERT_TRUE(answer.has_value());
    EXPECT_EQ(*answer, insidePolygon(outline, point.X() - t * lean.X(), point.Y() - t * lean.Y()));
  }
}

TEST(RuledPrism, LinesThatMeetAtAnApexHoldThePointsWhoseProjectionFromItIsInside) {
  // The square [0, 2]² at z = 0 seen from (1, 1, 4): the sides are planes, the prism a frustum
  // between z = -2 and z = 2 (the lines reach half way to the apex).
  const std::vector<gp_Pnt> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const gp_Pnt apex(1, 1, 4);
  std::vector<gp_Vec> towardsApex;
  for (const gp_Pnt& corner : square) towardsApex.emplace_back(corner, apex);
  const RuledPrism prism(square, towardsApex, 0.5);
  for (const gp_Pnt& point : gridPoints(-1.9, 1.9)) {
    const double scale = 4.0 / (4.0 - point.Z());  // from the point's height down to z = 0
    const double x = 1.0 + (point.X() - 1.0) * scale, y = 1.0 + (point.Y() - 1.0) * scale;
    if (std::abs(x) < 1e-6 || std::abs(x - 2.0) < 1e-6 || std::abs(y) < 1e-6 || std::abs(y - 2.0) < 1e-6) continue;
    const std::optional<bool> answer = prism.contains(point);
    ASSERT_TRUE(answer.has_value());
    EXPECT_EQ(*answer, insidePolygon(square, x, y)) << point.X() << " " << point.Y() << " " << point.Z();
  }
}

TEST(RuledPrism, TwistedSidesSeparateTheTwoEndsOutlines) {
  // The lines of a square's corners lean each its own way: the sides are bilinear, not planes.
  // A point at the height where the lines reach is inside exactly where the outline there is.
  const std::vector<gp_Pnt> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const std::vector<gp_Vec> leans{{0.5, 0, 1}, {0, 0.5, 1}, {-0.5, 0, 1}, {0, -0.5, 1}};
  const RuledPrism prism(square, leans, 1.0);
  std::vector<gp_Pnt> top;  // the outline at z = 0.999: each corner moved along its line
  for (std::size_t k = 0; k < square.size(); ++k) top.push_back(square[k].Translated(0.999 * leans[k]));
  for (const gp_Pnt& point : gridPoints(0.999, 0.999)) {
    const std::optional<bool> answer = prism.contains(point);
    ASSERT_TRUE(answer.has_value());
    EXPECT_EQ(*answer, insidePolygon(top, point.X(), point.Y())) << point.X() << " " << point.Y();
  }
}

TEST(RuledPrism, PointsBeyondTheLinesEndsAreOutside) {
  const std::vector<gp_Pnt> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const RuledPrism prism(square, std::vector<gp_Vec>(4, gp_Vec(0, 0, 1)), 1.0);
  EXPECT_EQ(prism.contains(gp_Pnt(1.0, 1.0, 0.5)), std::optional<bool>(true));
  EXPECT_EQ(prism.contains(gp_Pnt(1.0, 1.0, 1.5)), std::optional<bool>(false));
  EXPECT_EQ(prism.contains(gp_Pnt(1.0, 1.0, -1.5)), std::optional<bool>(false));
}

TEST(RuledPrism, APointOnASideIsLeftToTheGeneralClassification) {
  const std::vector<gp_Pnt> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const RuledPrism prism(square, std::vector<gp_Vec>(4, gp_Vec(0, 0, 1)), 1.0);
  EXPECT_FALSE(prism.contains(gp_Pnt(2.0, 0.7, 0.2)).has_value());
  EXPECT_FALSE(prism.contains(gp_Pnt(0.3, 0.0, -0.4)).has_value());
}

}  // namespace
}  // namespace airshape::geometry
