#include "vessel_of_revolution.h"

#include <cmath>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <GC_MakeSegment.hxx>
#include <GProp_GProps.hxx>
#include <GeomConvert.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"

namespace airshape::tank {

namespace {

/// The edge of a meridian curve as a B-spline (conic arcs exactly, as rational ones): CAD
/// exchange keeps B-spline surfaces of revolution whole, where STEP readers took arcs of
/// ellipses trimmed by angle for less than they are.
TopoDS_Edge edgeOf(const Handle(Geom_Curve) & curve) {
  return BRepBuilderAPI_MakeEdge(Handle(Geom_Curve)(GeomConvert::CurveToBSplineCurve(curve))).Edge();
}

}  // namespace

NamedShape vesselOfRevolution(const DomeMeridian& dome, double cylinderRadius, double cylinderLength,
                              const std::string& uid) {
  const double middle = dome.depth + 0.5 * cylinderLength;
  if (middle <= 0.0) throw Error(ErrorCode::InvalidModel, "the vessel has no length (no cylinder, flat domes)");
  // The rear dome is the front one mirrored in the plane through the cylinder's middle.
  gp_Trsf mirror;
  mirror.SetMirror(gp_Ax2(gp_Pnt(middle, 0, 0), gp_Dir(1, 0, 0)));
  // The meridian from the front apex over the cylinder to the rear apex, closed along the
  // axis: it bounds a planar face whose revolution is the solid.
  BRepBuilderAPI_MakeWire wire;
  for (const Handle(Geom_Curve) & curve : dome.curves) wire.Add(edgeOf(curve));
  if (cylinderLength > 0.0)
    wire.Add(
        edgeOf(GC_MakeSegment(gp_Pnt(dome.depth, 0, cylinderRadius), gp_Pnt(2 * middle - dome.depth, 0, cylinderRadius))
                   .Value()));
  for (auto curve = dome.curves.rbegin(); curve != dome.curves.rend(); ++curve)
    wire.Add(edgeOf(Handle(Geom_Curve)::DownCast((*curve)->Transformed(mirror))->Reversed()));
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(2 * middle, 0, 0), gp_Pnt(0, 0, 0)).Edge());
  if (!wire.IsDone()) throw Error(ErrorCode::InvalidModel, "the vessel's meridian is not connected");
  BRepBuilderAPI_MakeFace section(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0)), wire.Wire());
  BRepPrimAPI_MakeRevol revolution(section.Face(), gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)));
  if (!revolution.IsDone()) throw Error(ErrorCode::InvalidModel, "the vessel's meridian cannot be revolved");
  NamedShape vessel;
  TopExp_Explorer solid(revolution.Shape(), TopAbs_SOLID);
  if (!solid.More()) throw Error(ErrorCode::InvalidModel, "the vessel's revolution is no solid");
  vessel.shape = geometry::outwards(TopoDS::Solid(solid.Current()));
  // The faces by where they lie along the axis: the cylinder about the middle, the domes
  // (with their lids) before and behind it.
  for (TopExp_Explorer face(vessel.shape, TopAbs_FACE); face.More(); face.Next()) {
    GProp_GProps properties;
    BRepGProp::SurfaceProperties(face.Current(), properties);
    const double x = properties.CentreOfMass().X();
    const bool cylinder = cylinderLength > 0.0 && std::abs(x - middle) < 1e-9 * middle;
    vessel.faces.emplace_back(uid + (cylinder     ? "/cylinder"
                                     : x < middle ? "/front dome"
                                                  : "/rear dome"),
                              TopoDS::Face(face.Current()));
  }
  return vessel;
}

}  // namespace airshape::tank
