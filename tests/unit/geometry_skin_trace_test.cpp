// Where a plane meets a skin (skin_crossing.h) when it meets it in runs of faces apart from each
// other, as a box wing's lower and upper wings: the trace takes the run where its lines are set
// up, where it gave up before.
#include <gtest/gtest.h>

#include "airshape/geometry/skin_trace.h"
#include "test_wing_skins.h"

namespace airshape::geometry {
namespace {

/// Two skins of the small wing side by side: one as it is (y from 0 to 1), one shifted by 3
/// along y.
TopoDS_Shape twoWingsApart() { return test::upperSkinWithCopy(gp_Vec(0, 3, 0)); }

// A plane along the span at x = 0.5: its lines run up (along z) from points along y, t = 0 at
// y = 0 and t = 1 at y = 1.
const CrossingLines kAlongSpan{gp_Pnt(0.5, 0.0, -1.0), gp_Vec(0, 1, 0), gp_Vec(0, 0, 1)};

TEST(SkinCrossing, TakesTheRunOfFacesWhereItsLinesAreSetUp) {
  const TopoDS_Shape skin = twoWingsApart();
  const auto span = crossingSpan(skin, kAlongSpan, 1e-9);
  ASSERT_TRUE(span.has_value());
  EXPECT_NEAR(span->first, 0.0, 1e-9);
  EXPECT_NEAR(span->second, 1.0, 1e-9);

  const auto crossing = traceSkinCrossing(skin, kAlongSpan, CrossingEnd::open(), CrossingEnd::open(), 1e-9);
  ASSERT_TRUE(crossing.has_value());
  EXPECT_NEAR(crossing->start().Y(), 0.0, 1e-9);
  EXPECT_NEAR(crossing->end().Y(), 1.0, 1e-9);
  EXPECT_NEAR(crossing->start().X(), 0.5, 1e-9);
}

TEST(SkinCrossing, TakesTheOtherRunWhereTheLinesAreSetUpThere) {
  const CrossingLines atTheOther{gp_Pnt(0.5, 3.0, -1.0), gp_Vec(0, 1, 0), gp_Vec(0, 0, 1)};
  const auto span = crossingSpan(twoWingsApart(), atTheOther, 1e-9);
  ASSERT_TRUE(span.has_value());
  EXPECT_NEAR(span->first, 0.0, 1e-9);
  EXPECT_NEAR(span->second, 1.0, 1e-9);
}

TEST(SkinCrossing, GivesNothingWhereBothRunsMeetItsLines) {
  // t from 0 to 1 now reaches from y = 0.5 to 3.5: both runs, so which is meant is unclear.
  const CrossingLines acrossBoth{gp_Pnt(0.5, 0.5, -1.0), gp_Vec(0, 3, 0), gp_Vec(0, 0, 1)};
  EXPECT_FALSE(crossingSpan(twoWingsApart(), acrossBoth, 1e-9).has_value());
  EXPECT_FALSE(
      traceSkinCrossing(twoWingsApart(), acrossBoth, CrossingEnd::open(), CrossingEnd::open(), 1e-9).has_value());
}

}  // namespace
}  // namespace airshape::geometry
