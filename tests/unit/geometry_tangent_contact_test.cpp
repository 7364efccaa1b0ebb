// Lines along which a plane face touches a curved face without crossing it: plates laid on a
// tube of radius 1 about the x axis (an exact rational B-spline cylinder), as a wing's root laid
// on a fuselage's side. The plate in the tube's tangent plane y = 1 touches it along the line
// y = 1, z = 0 over the plate's length; a plate that cuts the tube, one beside it, a flat patch
// lying in the plate's plane and a patch that only ends on it touch it along no line.
#include <cmath>

#include <gtest/gtest.h>
#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Builder.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax3.hxx>

#include "airshape/geometry/tangent_contact.h"
#include "tube_skin.h"

namespace airshape::geometry {
namespace {

constexpr double kTolerance = 1e-7;

TopoDS_Shape tube() { return test::tubeSkin(1.0); }

/// A plane face at y = `y` over x in [x0, x1] and z in [z0, z1].
TopoDS_Shape plateAtY(double y, double x0, double x1, double z0, double z1) {
  BRepBuilderAPI_MakePolygon outline(gp_Pnt(x0, y, z0), gp_Pnt(x1, y, z0), gp_Pnt(x1, y, z1), gp_Pnt(x0, y, z1), true);
  return BRepBuilderAPI_MakeFace(outline.Wire(), true).Face();
}

/// The same rectangle as a flat B-spline patch (not an OCCT plane).
TopoDS_Shape flatPatchAtY(double y, double x0, double x1, double z0, double z1) {
  const Handle(Geom_Plane) plane = new Geom_Plane(gp_Ax3(gp_Pnt(0, y, 0), gp_Dir(0, 1, 0), gp_Dir(1, 0, 0)));
  const Handle(Geom_RectangularTrimmedSurface) piece = new Geom_RectangularTrimmedSurface(plane, x0, x1, -z1, -z0);
  return BRepBuilderAPI_MakeFace(GeomConvert::SurfaceToBSplineSurface(piece), 1e-9).Face();
}

double lengthOf(const TopoDS_Edge& edge) { return GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge)); }

TEST(TangentContact, APlateOnTheTubesSideTouchesItAlongItsLength) {
  const auto edges = withTangentContacts({}, plateAtY(1.0, 1.0, 3.0, -0.5, 0.5), tube(), kTolerance);
  ASSERT_TRUE(edges);
  ASSERT_EQ(edges->size(), 1u);
  EXPECT_NEAR(lengthOf(edges->front()), 2.0, 1e-9);
  const BRepAdaptor_Curve line(edges->front());
  const gp_Pnt middle = line.Value(0.5 * (line.FirstParameter() + line.LastParameter()));
  EXPECT_NEAR(middle.Distance(gp_Pnt(2.0, 1.0, 0.0)), 0.0, 1e-6);
}

TEST(TangentContact, ALineAlongThePatchsSeamIsFoundOnce) {
  BRepBuilderAPI_MakePolygon outline(gp_Pnt(1, -0.5, 1), gp_Pnt(3, -0.5, 1), gp_Pnt(3, 0.5, 1), gp_Pnt(1, 0.5, 1),
                                     true);
  const auto edges = withTangentContacts({}, BRepBuilderAPI_MakeFace(outline.Wire(), true).Face(), tube(), kTolerance);
  ASSERT_TRUE(edges);
  ASSERT_EQ(edges->size(), 1u);
  EXPECT_NEAR(lengthOf(edges->front()), 2.0, 1e-9);
}

TEST(TangentContact, EitherShapeMayHoldThePlane) {
  const auto edges = withTangentContacts({}, tube(), plateAtY(-1.0, 0.5, 3.0, -0.5, 0.5), kTolerance);
  ASSERT_TRUE(edges);
  ASSERT_EQ(edges->size(), 1u);
  EXPECT_NEAR(lengthOf(edges->front()), 2.5, 1e-9);
}

TEST(TangentContact, ALineEndsWhereItLeavesThePlate) {
  // The plate reaches beyond the tube's end at x = 4: the contact stops there.
  const auto edges = withTangentContacts({}, plateAtY(1.0, 3.0, 5.0, -0.5, 0.5), tube(), kTolerance);
  ASSERT_TRUE(edges);
  ASSERT_EQ(edges->size(), 1u);
  EXPECT_NEAR(lengthOf(edges->front()), 1.0, 1e-6);
}

TEST(TangentContact, PlatesThatCutOrMissTheTubeTouchItNowhere) {
  EXPECT_FALSE(withTangentContacts({}, plateAtY(0.5, 1.0, 3.0, -0.5, 0.5), tube(), kTolerance));
  EXPECT_FALSE(withTangentContacts({}, plateAtY(1.0, 5.0, 6.0, -0.5, 0.5), tube(), kTolerance));
  EXPECT_FALSE(withTangentContacts({}, plateAtY(1.0, 1.0, 3.0, 0.5, 0.9), tube(), kTolerance));
}

TEST(TangentContact, AFaceInThePlaneOrEndingOnItDoesNotTouchIt) {
  // Lying in the plate's plane (a half model's symmetry face under a wing's root).
  EXPECT_FALSE(
      withTangentContacts({}, plateAtY(1.0, 1.0, 3.0, -0.5, 0.5), flatPatchAtY(1.0, 0.0, 4.0, -1.0, 1.0), kTolerance));
  // A half tube ending on the plane y = 0 along two lines: its edges, no tangency.
  const TopoDS_Shape halfTube = test::tubeSkin(1.0, M_PI);
  EXPECT_FALSE(withTangentContacts({}, plateAtY(0.0, 1.0, 3.0, -2.0, 2.0), halfTube, kTolerance));
}

TEST(TangentContact, SectionEdgesAlongTheContactAreReplacedAndOthersKept) {
  // A section that found a piece of the contact, and an edge elsewhere.
  const TopoDS_Edge piece = BRepBuilderAPI_MakeEdge(gp_Pnt(1.0, 1.0, 0.0), gp_Pnt(2.0, 1.0, 0.0)).Edge();
  const TopoDS_Edge elsewhere = BRepBuilderAPI_MakeEdge(gp_Pnt(0.0, -1.0, 0.0), gp_Pnt(0.0, 0.0, -1.0)).Edge();
  const auto edges = withTangentContacts({piece, elsewhere}, plateAtY(1.0, 1.0, 3.0, -0.5, 0.5), tube(), kTolerance);
  ASSERT_TRUE(edges);
  ASSERT_EQ(edges->size(), 2u);
  double total = 0;
  for (const TopoDS_Edge& edge : *edges) total += lengthOf(edge);
  EXPECT_NEAR(total, 2.0 + std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace airshape::geometry
