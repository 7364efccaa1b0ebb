// The tight box of a shape (box_answer.h) against boxes known in closed form: it is the union of
// its faces', free edges' and free vertices' exact boxes, though only the parts that may hold an
// extreme are measured exactly.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BezierCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include "airshape/query/box_answer.h"

namespace airshape::query {
namespace {

/// OCCT widens the exact box of some surfaces by the modelling tolerance, 1e-7.
constexpr double kWidened = 1.01e-7;

void expectBox(const Bnd_Box& box, double x1, double y1, double z1, double x2, double y2, double z2) {
  double a1, b1, c1, a2, b2, c2;
  box.Get(a1, b1, c1, a2, b2, c2);
  EXPECT_NEAR(a1, x1, kWidened);
  EXPECT_NEAR(b1, y1, kWidened);
  EXPECT_NEAR(c1, z1, kWidened);
  EXPECT_NEAR(a2, x2, kWidened);
  EXPECT_NEAR(b2, y2, kWidened);
  EXPECT_NEAR(c2, z2, kWidened);
}

/// The parabola arc from (0, 0, 0) to (2, 0, 0) whose control points reach y = 2 but which
/// reaches only y = 1, at its middle.
TopoDS_Edge parabolaArc() {
  TColgp_Array1OfPnt poles(1, 3);
  poles(1) = gp_Pnt(0, 0, 0);
  poles(2) = gp_Pnt(1, 2, 0);
  poles(3) = gp_Pnt(2, 0, 0);
  return BRepBuilderAPI_MakeEdge(new Geom_BezierCurve(poles)).Edge();
}

TEST(TightBox, OfASolidIsItsExactExtent) {
  // A torus about z of radii 3 and 1: its control points reach well beyond it.
  expectBox(tightBox(BRepPrimAPI_MakeTorus(3.0, 1.0).Shape()), -4, -4, -1, 4, 4, 1);
}

TEST(TightBox, TakesEveryKindOfPart) {
  // A unit sphere, a free circle of radius 2 about (10, 0, 5) in the plane z = 5 and a free
  // vertex: each holds some of the six extremes, and each part lies inside the others' rough
  // boxes in some direction.
  BRep_Builder builder;
  TopoDS_Compound parts;
  builder.MakeCompound(parts);
  builder.Add(parts, BRepPrimAPI_MakeSphere(1.0).Shape());
  builder.Add(parts, BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(10, 0, 5), gp::DZ()), 2.0)).Edge());
  builder.Add(parts, BRepBuilderAPI_MakeVertex(gp_Pnt(-3, 7, -4)).Vertex());
  expectBox(tightBox(parts), -3, -2, -4, 12, 7, 5);
}

TEST(TightBox, TakesAPartWhoseRoughBoxLiesWithinAnother) {
  // The arc's control points reach y = 2, beyond the vertex at y = 1.5, but the arc itself
  // stays below it: the vertex holds the highest y.
  BRep_Builder builder;
  TopoDS_Compound parts;
  builder.MakeCompound(parts);
  builder.Add(parts, parabolaArc());
  expectBox(tightBox(parts), 0, 0, 0, 2, 1, 0);
  builder.Add(parts, BRepBuilderAPI_MakeVertex(gp_Pnt(1, 1.5, 0)).Vertex());
  expectBox(tightBox(parts), 0, 0, 0, 2, 1.5, 0);
}

TEST(TightBox, OfNothingIsVoid) { EXPECT_TRUE(tightBox(TopoDS_Compound()).IsVoid()); }

}  // namespace
}  // namespace airshape::query
