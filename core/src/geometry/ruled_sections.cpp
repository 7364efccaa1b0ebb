#include "airshape/geometry/ruled_sections.h"

#include <cmath>
#include <optional>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepLib.hxx>
#include <BRepTools_ReShape.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>

#include "airshape/core_module.h"
#include "airshape/geometry/brep_building.h"

namespace airshape::geometry {

namespace {

/// The module, loaded on first use and never unloaded: shapes built through it hold OCCT types
/// of the toolkits it brought along, and such shapes (cached by configurations) may be destroyed
/// after every static, when an unloaded toolkit's code would be gone.
const boost::dll::shared_library& rulingModule() {
  static const auto* module = new boost::dll::shared_library(
      loadCoreModule("libairshape_ruled_sections.so", "the ruled loft through sections"));
  return *module;
}

/// The face on a plane with the same wires as `face` (taken forward), the plane's normal turned
/// the way the face's surface points at its middle, so that the face keeps its side of the solid.
TopoDS_Face onPlane(const TopoDS_Face& face, gp_Pln plane) {
  const BRepAdaptor_Surface surface(face, false);
  gp_Pnt middle;
  gp_Vec alongU, alongV;
  surface.D1(0.5 * (surface.FirstUParameter() + surface.LastUParameter()),
             0.5 * (surface.FirstVParameter() + surface.LastVParameter()), middle, alongU, alongV);
  if (alongU.Crossed(alongV).Dot(gp_Vec(plane.Axis().Direction())) < 0.0)
    plane = gp_Pln(plane.Location(), plane.Axis().Direction().Reversed());
  BRep_Builder builder;
  TopoDS_Face flat;
  builder.MakeFace(flat, new Geom_Plane(plane), BRep_Tool::Tolerance(face));
  TopTools_ListOfShape edges;
  for (TopoDS_Iterator wire(face.Oriented(TopAbs_FORWARD)); wire.More(); wire.Next()) {
    builder.Add(flat, wire.Value());
    for (TopExp_Explorer edge(wire.Value(), TopAbs_EDGE); edge.More(); edge.Next()) edges.Append(edge.Current());
  }
  BRepLib::BuildPCurveForEdgesOnPlane(edges, flat);
  return flat;
}

/// The plane of a B-spline surface whose poles all lie within `flatness` of one (then so does
/// the surface, within their hull); nothing otherwise. (OCCT's GeomLib_IsPlanarSurface, tried
/// first, called a flat four-pole face of a unit-sized loft curved at this flatness.)
std::optional<gp_Pln> planeOfPoles(const Geom_BSplineSurface& surface, double flatness) {
  std::vector<gp_Pnt> poles;
  for (int u = 1; u <= surface.NbUPoles(); ++u)
    for (int v = 1; v <= surface.NbVPoles(); ++v) poles.push_back(surface.Pole(u, v));
  return planeThroughPoints(poles, flatness);
}

/// OCCT lofts even a flat ruled face as a B-spline surface; its Booleans intersect a plane with
/// a lifting surface's many-knotted skins by a far cheaper method than two B-splines (the eleven devices'
/// cut-outs of CPACS_30_aircraft_flaps.xml's main surface: 1.26 -> 1.10 s). So the loft's faces flat to a billionth of
/// its size become planes: the same points (a ruled face between straight edges in one plane is that plane), the same
/// edges.
void flatFacesAsPlanes(RuledSections& loft) {
  Bnd_Box box;
  BRepBndLib::Add(loft.solid, box);
  const double flatness = 1e-9 * std::sqrt(box.SquareExtent());
  BRepTools_ReShape reshape;
  bool any = false;
  for (TopExp_Explorer explorer(loft.solid, TopAbs_FACE); explorer.More(); explorer.Next()) {
    const TopoDS_Face face = TopoDS::Face(explorer.Current());
    const auto surface = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));
    if (surface.IsNull()) continue;
    const std::optional<gp_Pln> plane = planeOfPoles(*surface, flatness);
    if (!plane) continue;
    reshape.Replace(face.Oriented(TopAbs_FORWARD), onPlane(face, *plane));
    any = true;
  }
  if (!any) return;
  loft.solid = reshape.Apply(loft.solid);
  loft.firstCap = reshape.Value(loft.firstCap);
  loft.lastCap = reshape.Value(loft.lastCap);
}

}  // namespace

RuledSections ruledThroughSections(const std::vector<TopoDS_Wire>& wires) {
  using Entry = void(const std::vector<TopoDS_Wire>&, TopoDS_Shape&, TopoDS_Shape&, TopoDS_Shape&);
  RuledSections loft;
  rulingModule().get<Entry>("airshape_ruled_sections")(wires, loft.solid, loft.firstCap, loft.lastCap);
  if (!loft.solid.IsNull()) flatFacesAsPlanes(loft);
  return loft;
}

TopoDS_Face ruledFaceBetween(const TopoDS_Edge& first, const TopoDS_Edge& second) {
  using Entry = void(const TopoDS_Edge&, const TopoDS_Edge&, TopoDS_Face&);
  TopoDS_Face face;
  rulingModule().get<Entry>("airshape_ruled_face")(first, second, face);
  return face;
}

}  // namespace airshape::geometry
