// The part of a bilinear side between bounds, made from where its lines meet a skin: strips in a
// tube of radius 1 (an exact rational B-spline cylinder), bounded by rays from inside up to the
// skin and down to it, whose areas are known in closed form; a strip whose rays leave through
// the tube's open end is declined.
#include <cmath>

#include <gtest/gtest.h>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include "airshape/geometry/ruled_side.h"
#include "tube_skin.h"

namespace airshape::geometry {
namespace {

double areaOf(const TopoDS_Face& face) {
  GProp_GProps properties;
  BRepGProp::SurfaceProperties(face, properties);
  return properties.Mass();
}

constexpr double kTolerance = 1e-9;

TEST(RuledSide, AStripFromItsBaseUpToTheSkinHasTheAreaBelowTheArc) {
  const TopoDS_Shape tube = test::tubeSkin(1.0);
  // Lines straight up from y = 0.3, z = 0 at x = 1 and x = 3, three units long.
  const RuledSide side = ruledSide({1, 0.3, 0}, {1, 0.3, 3}, {3, 0.3, 0}, {3, 0.3, 3});
  const auto part = sidePart(side, {SideBound::Kind::Start}, {SideBound::Kind::Skin, &tube, 0.0, +1}, kTolerance);
  ASSERT_TRUE(part.has_value());
  ASSERT_FALSE(part->IsNull());
  EXPECT_NEAR(areaOf(*part), 2 * std::sqrt(1 - 0.3 * 0.3), 1e-9);
}

TEST(RuledSide, AStripExtrudedBothWaysReachesTheSkinAboveAndBelow) {
  const TopoDS_Shape tube = test::tubeSkin(1.0);
  // The lines run from z = -3 to 3; their middle (the base) lies inside the tube.
  const RuledSide side = ruledSide({1, 0.3, -3}, {1, 0.3, 3}, {3, 0.3, -3}, {3, 0.3, 3});
  const auto part =
      sidePart(side, {SideBound::Kind::Skin, &tube, 0.5, -1}, {SideBound::Kind::Skin, &tube, 0.5, +1}, kTolerance);
  ASSERT_TRUE(part.has_value());
  EXPECT_NEAR(areaOf(*part), 2 * 2 * std::sqrt(1 - 0.3 * 0.3), 1e-9);
}

TEST(RuledSide, ALeaningStripThroughTheAxisReachesTheSkinOneUnitAway) {
  const TopoDS_Shape tube = test::tubeSkin(1.0);
  // The plane y = z tan(30°) through the axis leans by 30°: its lines from the axis reach the
  // skin one unit away, so the part is a rectangle two long and one wide.
  const gp_Vec along(0, std::sin(M_PI / 6), std::cos(M_PI / 6));
  const RuledSide side =
      ruledSide({1, 0, 0}, gp_Pnt(1, 0, 0).Translated(3 * along), {3, 0, 0}, gp_Pnt(3, 0, 0).Translated(3 * along));
  const auto part = sidePart(side, {SideBound::Kind::Start}, {SideBound::Kind::Skin, &tube, 0.0, +1}, kTolerance);
  ASSERT_TRUE(part.has_value());
  EXPECT_NEAR(areaOf(*part), 2.0, 1e-9);
}

TEST(RuledSide, RaysLeavingThroughTheOpenEndAreDeclined) {
  const TopoDS_Shape tube = test::tubeSkin(1.0);
  // From x = 3 to x = 5: the rays beyond x = 4 miss the skin.
  const RuledSide side = ruledSide({3, 0.3, 0}, {3, 0.3, 3}, {5, 0.3, 0}, {5, 0.3, 3});
  EXPECT_FALSE(
      sidePart(side, {SideBound::Kind::Start}, {SideBound::Kind::Skin, &tube, 0.0, +1}, kTolerance).has_value());
}

}  // namespace
}  // namespace airshape::geometry
