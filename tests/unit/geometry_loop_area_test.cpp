// The area closed lines in a plane enclose, as a solid's cross-section: holes taken off,
// islands in them added again, and no answer where the lines cross.
#include <vector>

#include <gtest/gtest.h>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include "airshape/geometry/loop_area.h"

namespace airshape::geometry {
namespace {

/// The square of side `side` centred at (x, y) in the plane z = 0, as a closed wire.
TopoDS_Wire square(double x, double y, double side) {
  const double h = side / 2.0;
  return BRepBuilderAPI_MakePolygon(gp_Pnt(x - h, y - h, 0), gp_Pnt(x + h, y - h, 0), gp_Pnt(x + h, y + h, 0),
                                    gp_Pnt(x - h, y + h, 0), true)
      .Wire();
}

TEST(LoopArea, AHoleIsTakenOffAndAnIslandInItAddedAgain) {
  const gp_Pln plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  EXPECT_NEAR(*areaInsideLoops(plane, {square(0, 0, 4)}), 16.0, 1e-12);
  EXPECT_NEAR(*areaInsideLoops(plane, {square(0, 0, 4), square(0, 0, 2)}), 16.0 - 4.0, 1e-12);
  EXPECT_NEAR(*areaInsideLoops(plane, {square(0, 0, 2), square(0, 0, 4), square(0, 0, 1)}), 16.0 - 4.0 + 1.0, 1e-12);
  EXPECT_NEAR(*areaInsideLoops(plane, {square(0, 0, 1), square(5, 0, 1)}), 2.0, 1e-12);  // apart
}

TEST(LoopArea, LinesThatCrossBoundNoRegionsAndGiveNoArea) {
  const gp_Pln plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  EXPECT_FALSE(areaInsideLoops(plane, {square(0, 0, 2), square(1, 1, 2)}).has_value());
  const TopoDS_Wire figureEight =
      BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0), gp_Pnt(2, 0, 0), gp_Pnt(0, 2, 0), true).Wire();
  EXPECT_FALSE(areaInsideLoops(plane, {figureEight}).has_value());
}

}  // namespace
}  // namespace airshape::geometry
