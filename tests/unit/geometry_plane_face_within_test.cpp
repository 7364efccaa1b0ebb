// A plane face bounded by a wire that leaves the plane (a riffled bulkhead): valid, its area the
// area inside the wire seen along the normal, its box the wire's.
#include <gtest/gtest.h>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <Bnd_Box.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/plane_face_within.h"

namespace airshape::geometry {
namespace {

const gp_Pln kMidPlane(gp_Pnt(0.5, 0, 0), gp_Dir(1, 0, 0));

/// The square of side 2 about the x axis, its corners at x = 0 and 1 in turn.
TopoDS_Wire riffledSquare(bool closed) {
  return BRepBuilderAPI_MakePolygon(gp_Pnt(0, -1, -1), gp_Pnt(1, 1, -1), gp_Pnt(0, 1, 1), gp_Pnt(1, -1, 1), closed)
      .Wire();
}

TEST(PlaneFaceWithin, ARiffledSquareBoundsTheSquareSeenAlongTheNormal) {
  const TopoDS_Face face = planeFaceWithin(kMidPlane, riffledSquare(true));
  EXPECT_TRUE(BRepCheck_Analyzer(face).IsValid());
  EXPECT_NEAR(areaOf(face), 4.0, 1e-12);
  Bnd_Box box;
  BRepBndLib::AddOptimal(face, box, false, false);  // as the bounding_box op measures: without tolerances
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  EXPECT_NEAR(x0, 0.0, 1e-6);
  EXPECT_NEAR(x1, 1.0, 1e-6);
  EXPECT_NEAR(y1 - y0, 2.0, 1e-6);
  // The wire's turn does not matter: the face's normal is the plane's either way.
  EXPECT_NEAR(areaOf(planeFaceWithin(kMidPlane, TopoDS::Wire(riffledSquare(true).Reversed()))), 4.0, 1e-12);
}

TEST(PlaneFaceWithin, AnOpenWireIsAnError) { EXPECT_THROW(planeFaceWithin(kMidPlane, riffledSquare(false)), Error); }

}  // namespace
}  // namespace airshape::geometry
