// Where the lines of a ruled surface meet a skin (ruled_crossing.h) when they meet it twice: far
// off, as a box wing's other wing, the meeting nearest the lines' bases counts; close by, the
// skin folds back over itself and the crossing is left to the Boolean operation.
#include <gtest/gtest.h>

#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include "bspline_patch.h"
#include "ruled_crossing.h"
#include "test_wing_skins.h"

namespace airshape::structure {
namespace {

/// The small wing's upper skin and a copy of it lifted by `lift` along z, as one skin.
std::vector<Patch> skinWithCopyAbove(double lift) {
  TopoDS_Compound skin;
  BRep_Builder builder;
  builder.MakeCompound(skin);
  builder.Add(skin, test::upperSkin());
  TopoDS_Shape lifted = test::upperSkin();
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(0, 0, lift));
  lifted.Move(TopLoc_Location(shift));
  builder.Add(skin, lifted);
  return skinPatches(skin)->patches;
}

// Lines up along z from the chord plane at x = 0.5, from y = 0.2 to 0.8.
const RuledLines kUpFromChord{gp_Pnt(0.5, 0.2, 0.0), gp_Pnt(0.5, 0.8, 0.0), gp_Vec(0, 0, 1), gp_Vec(0, 0, 1)};

TEST(RuledCrossing, TakesTheNearSkinWhereTheLinesMeetAnotherFarOff) {
  const auto pieces = ruledCrossing(skinWithCopyAbove(3.0), kUpFromChord, 1e-9);
  ASSERT_TRUE(pieces.has_value());
  ASSERT_EQ(pieces->size(), 1u);
  EXPECT_EQ(pieces->front().patch, 0u);  // the skin as it is, not the lifted copy
  for (const PatchPoint& point : pieces->front().points) EXPECT_LT(point.point.Z(), 0.1);
  EXPECT_NEAR(pieces->front().points.front().point.Y(), 0.2, 1e-9);
  EXPECT_NEAR(pieces->front().points.back().point.Y(), 0.8, 1e-9);
}

TEST(RuledCrossing, RefusesASkinThatFoldsBackCloseBy) {
  EXPECT_THROW(ruledCrossing(skinWithCopyAbove(0.2), kUpFromChord, 1e-9), FoldedSkin);
}

}  // namespace
}  // namespace airshape::structure
