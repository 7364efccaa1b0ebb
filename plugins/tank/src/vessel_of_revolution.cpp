#include "vessel_of_revolution.h"

#include <utility>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <GC_MakeSegment.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"

namespace airshape::tank {

namespace {

/// A meridian edge and the name of the face it sweeps.
using NamedEdge = std::pair<std::string, TopoDS_Edge>;

TopoDS_Edge edgeOf(const Handle(Geom_Curve) & curve) { return BRepBuilderAPI_MakeEdge(curve).Edge(); }

}  // namespace

NamedShape vesselOfRevolution(const DomeMeridian& dome, double cylinderRadius, double cylinderLength,
                              const std::string& uid) {
  const double middle = dome.depth + 0.5 * cylinderLength;
  if (middle <= 0.0) throw Error(ErrorCode::InvalidModel, "the vessel has no length (no cylinder, flat domes)");
  // The rear dome is the front one mirrored in the plane through the cylinder's middle.
  gp_Trsf mirror;
  mirror.SetMirror(gp_Ax2(gp_Pnt(middle, 0, 0), gp_Dir(1, 0, 0)));
  std::vector<NamedEdge> meridian;
  for (const Handle(Geom_Curve) & curve : dome.curves) meridian.emplace_back(uid + "/front dome", edgeOf(curve));
  if (cylinderLength > 0.0)
    meridian.emplace_back(uid + "/cylinder", edgeOf(GC_MakeSegment(gp_Pnt(dome.depth, 0, cylinderRadius),
                                                                   gp_Pnt(2 * middle - dome.depth, 0, cylinderRadius))
                                                        .Value()));
  for (auto curve = dome.curves.rbegin(); curve != dome.curves.rend(); ++curve) {
    Handle(Geom_Curve) mirrored = Handle(Geom_Curve)::DownCast((*curve)->Transformed(mirror));
    meridian.emplace_back(uid + "/rear dome", edgeOf(mirrored->Reversed()));
  }
  // Closed along the axis, the meridian bounds a planar face whose revolution is the solid.
  BRepBuilderAPI_MakeWire wire;
  for (const auto& [name, edge] : meridian) wire.Add(edge);
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(2 * middle, 0, 0), gp_Pnt(0, 0, 0)).Edge());
  if (!wire.IsDone()) throw Error(ErrorCode::InvalidModel, "the vessel's meridian is not connected");
  BRepBuilderAPI_MakeFace section(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0)), wire.Wire());
  BRepPrimAPI_MakeRevol revolution(section.Face(), gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)));
  if (!revolution.IsDone()) throw Error(ErrorCode::InvalidModel, "the vessel's meridian cannot be revolved");
  NamedShape vessel;
  TopExp_Explorer solid(revolution.Shape(), TopAbs_SOLID);
  if (!solid.More()) throw Error(ErrorCode::InvalidModel, "the vessel's revolution is no solid");
  vessel.shape = geometry::outwards(TopoDS::Solid(solid.Current()));
  // The faces by the meridian edge each one sweeps (faces of the solid, as the revolution
  // made them).
  for (const auto& [name, edge] : meridian)
    for (const TopoDS_Shape& face : revolution.Generated(edge))
      if (face.ShapeType() == TopAbs_FACE) vessel.faces.emplace_back(name, TopoDS::Face(face));
  return vessel;
}

}  // namespace airshape::tank
