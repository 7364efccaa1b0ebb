// Where lines meet a shape's faces (line_crossings.h), one shape prepared for many lines.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <TopoDS_Shape.hxx>

#include "line_crossings.h"

namespace airshape::controlsurfaces {
namespace {

TEST(LineCrossings, MeetsABoxInOrderAlongTheLine) {
  LineCrossings box(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(2, 1, 1)).Shape());
  for (const double y : {0.25, 0.5, 0.75}) {  // several lines, one preparation
    const std::vector<LineCrossing> hits = box.of(gp_Lin(gp_Pnt(-1, y, 0.5), gp_Dir(1, 0, 0)), 1e-9);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].along, 1.0, 1e-9);
    EXPECT_NEAR(hits[1].along, 3.0, 1e-9);
    EXPECT_NEAR(hits[0].point.Y(), y, 1e-12);
    EXPECT_NEAR(std::abs(hits[0].normal.Normalized().X()), 1.0, 1e-12);
  }
  EXPECT_TRUE(box.of(gp_Lin(gp_Pnt(-1, 2, 0.5), gp_Dir(1, 0, 0)), 1e-9).empty());
}

TEST(LineCrossings, ALineThroughAnEdgeCrossesOnce) {
  const std::vector<LineCrossing> hits =
      crossingsOf(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), gp_Lin(gp_Pnt(-1, -1, 0.5), gp_Dir(1, 1, 0)), 1e-7);
  EXPECT_EQ(hits.size(), 2u);  // through the edges x = y = 0 and x = y = 1
}

TEST(LineCrossings, AnEmptyShapeIsMetNowhere) {
  EXPECT_TRUE(crossingsOf(TopoDS_Shape(), gp_Lin(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), 1e-9).empty());
}

}  // namespace
}  // namespace airshape::controlsurfaces
