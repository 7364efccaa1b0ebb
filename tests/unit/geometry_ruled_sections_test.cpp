// The ruled loft through closed wires (ruled_sections.h): its flat faces are planes, its
// twisted faces stay ruled, every face keeps its side, and the solid's volume is that of the
// frustum the wires bound.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/ruled_sections.h"

namespace airshape::geometry {
namespace {

/// A closed polygon of straight edges given as degree-1 B-splines, as the outlines of devices
/// are: OCCT lofts those as B-spline faces even where they are flat (it makes planes only
/// between edges that are lines).
TopoDS_Wire closedPolygon(const std::vector<gp_Pnt>& corners) {
  BRepBuilderAPI_MakeWire wire;
  for (std::size_t k = 0; k < corners.size(); ++k)
    wire.Add(BRepBuilderAPI_MakeEdge(straightLine(corners[k], corners[(k + 1) % corners.size()])).Edge());
  return wire.Wire();
}

struct FaceKinds {
  int planes = 0, ruled = 0;
};

FaceKinds kindsOf(const TopoDS_Shape& shape) {
  FaceKinds kinds;
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next()) {
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(face.Current()));
    if (surface->IsKind(STANDARD_TYPE(Geom_Plane))) ++kinds.planes;
    if (surface->IsKind(STANDARD_TYPE(Geom_BSplineSurface))) ++kinds.ruled;
  }
  return kinds;
}

double volumeOf(const TopoDS_Shape& shape) {
  GProp_GProps properties;
  BRepGProp::VolumeProperties(shape, properties);
  return properties.Mass();
}

/// Whether every face of a convex solid points away from its centre of mass (a face turned the
/// wrong way points into it).
bool pointsOutwards(const TopoDS_Shape& solid) {
  GProp_GProps properties;
  BRepGProp::VolumeProperties(solid, properties);
  const gp_Pnt centre = properties.CentreOfMass();
  for (TopExp_Explorer explorer(solid, TopAbs_FACE); explorer.More(); explorer.Next()) {
    const TopoDS_Face& face = TopoDS::Face(explorer.Current());
    const BRepAdaptor_Surface surface(face);
    gp_Pnt middle;
    gp_Vec alongU, alongV;
    surface.D1(0.5 * (surface.FirstUParameter() + surface.LastUParameter()),
               0.5 * (surface.FirstVParameter() + surface.LastVParameter()), middle, alongU, alongV);
    gp_Vec normal = alongU.Crossed(alongV);
    if (face.Orientation() == TopAbs_REVERSED) normal.Reverse();
    if (normal.Dot(gp_Vec(centre, middle)) <= 0.0) return false;
  }
  return true;
}

bool holdsFace(const TopoDS_Shape& shape, const TopoDS_Shape& face) {
  for (TopExp_Explorer explorer(shape, TopAbs_FACE); explorer.More(); explorer.Next())
    if (explorer.Current().IsSame(face)) return true;
  return false;
}

/// A square pyramid of base side 2 at z = 0 and apex (0, 0, 2), its top cut off by the tilted
/// plane z = 1 + x / 5: its sides are flat, but no side's two edges are parallel, so OCCT lofts
/// them as B-spline faces.
struct TiltedFrustum {
  const gp_Pnt apex{0, 0, 2};
  std::vector<gp_Pnt> bottom{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, top;
  TiltedFrustum() {
    for (const gp_Pnt& corner : bottom) {
      const double t = (1.0 + 0.2 * corner.X()) / (2.0 + 0.2 * corner.X());  // where the edge meets the plane
      top.emplace_back(corner.XYZ() + t * (apex.XYZ() - corner.XYZ()));
    }
  }
  /// The pyramid's volume less that of the pyramid cut off (its base the top quadrilateral).
  double volume() const {
    const gp_Vec normal = gp_Vec(top[0], top[2]).Crossed(gp_Vec(top[1], top[3]));
    const double topArea = 0.5 * normal.Magnitude();
    const double apexHeight = std::abs(gp_Vec(top[0], apex).Dot(normal.Normalized()));
    return 4.0 * 2.0 / 3.0 - topArea * apexHeight / 3.0;
  }
  /// The ruled loft from the bottom square to the top quadrilateral.
  RuledSections lofted() const { return ruledThroughSections({closedPolygon(bottom), closedPolygon(top)}); }
};

/// A loft that closes into a valid solid whose faces all point outwards; its kinds of faces.
FaceKinds validKindsOf(const RuledSections& loft) {
  EXPECT_FALSE(loft.solid.IsNull());
  if (loft.solid.IsNull()) return {};
  EXPECT_TRUE(BRepCheck_Analyzer(loft.solid).IsValid());
  EXPECT_TRUE(pointsOutwards(loft.solid));
  return kindsOf(loft.solid);
}

TEST(RuledSections, FlatFacesBecomePlanes) {
  const TiltedFrustum frustum;
  const RuledSections loft = frustum.lofted();
  const FaceKinds kinds = validKindsOf(loft);
  EXPECT_EQ(kinds.planes, 6);
  EXPECT_EQ(kinds.ruled, 0);
  EXPECT_NEAR(volumeOf(loft.solid), frustum.volume(), 1e-9);
  EXPECT_TRUE(holdsFace(loft.solid, loft.firstCap));
  EXPECT_TRUE(holdsFace(loft.solid, loft.lastCap));
}

TEST(RuledSections, TwistedFacesStayRuled) {
  // One top corner moved within the top plane: the two sides through it are twisted, the
  // other two stay flat.
  TiltedFrustum frustum;
  gp_Pnt& moved = frustum.top[2];
  moved.SetX(moved.X() + 0.1);
  moved.SetZ(1.0 + 0.2 * moved.X());
  const FaceKinds kinds = validKindsOf(frustum.lofted());
  EXPECT_EQ(kinds.planes, 4);
  EXPECT_EQ(kinds.ruled, 2);
}

}  // namespace
}  // namespace airshape::geometry
