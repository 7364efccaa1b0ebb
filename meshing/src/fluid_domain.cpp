#include "fluid_domain.h"

#include <algorithm>
#include <cmath>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_Plane.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <gmsh.h>

#include "airshape/error.h"
#include "airshape/fused_shape.h"
#include "gmsh_session.h"
#include "labelled_shape.h"

namespace airshape::meshing {

namespace {

struct Box {
  gp_Pnt low, high;
};

Box boundingBox(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  if (box.IsVoid()) throw Error(ErrorCode::InvalidArgument, "the aircraft has no extent to put a far field around");
  return {box.CornerMin(), box.CornerMax()};
}

/// The far field's faces labelled: those in the plane y = 0 of a half domain "symmetry", the
/// others "farfield".
NamedShape labelledBoundary(const TopoDS_Shape& solid, bool symmetry) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  NamedShape boundary{solid, {}};
  for (int index = 1; index <= faces.Extent(); ++index) {
    const TopoDS_Face& face = TopoDS::Face(faces(index));
    const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(face));
    const bool inSymmetryPlane = symmetry && !plane.IsNull() && plane->Axis().Direction().IsParallel(gp::DY(), 1e-12) &&
                                 std::abs(plane->Location().Y()) < 1e-9;
    const std::string label = inSymmetryPlane ? "symmetry" : "farfield";
    boundary.faces.push_back(labelledFaces(face, label).faces.front());
  }
  return boundary;
}

TopoDS_Shape farfieldSolid(const Box& aircraft, const Farfield& farfield, bool symmetry, double distance) {
  const gp_Pnt centre((aircraft.low.XYZ() + aircraft.high.XYZ()) / 2);
  if (farfield.shape == Farfield::Shape::Sphere) {
    const double radius = aircraft.low.Distance(aircraft.high) / 2 + distance;
    if (!symmetry) return BRepPrimAPI_MakeSphere(centre, radius).Shape();
    // The half sphere y >= 0 around the centre moved into the symmetry plane.
    const gp_Pnt onPlane(centre.X(), 0, centre.Z());
    return BRepPrimAPI_MakeSphere(gp_Ax2(onPlane, gp::DY()), radius + std::abs(centre.Y()), 0, M_PI / 2).Shape();
  }
  const gp_Pnt low(aircraft.low.X() - distance, symmetry ? 0.0 : aircraft.low.Y() - distance,
                   aircraft.low.Z() - distance);
  const gp_Pnt high(aircraft.high.X() + distance, aircraft.high.Y() + distance, aircraft.high.Z() + distance);
  return BRepPrimAPI_MakeBox(low, high).Shape();
}

}  // namespace

double aircraftLength(const TopoDS_Shape& aircraft) {
  const Box box = boundingBox(aircraft);
  const gp_XYZ sides = box.high.XYZ() - box.low.XYZ();
  return std::max({sides.X(), sides.Y(), sides.Z()});
}

double farfieldDistance(const Farfield& farfield, double length) {
  return farfield.metres ? *farfield.metres : farfield.lengths * length;
}

NamedShape fluidDomain(const NamedShape& aircraft, const Farfield& farfield, bool symmetry) {
  const Box box = boundingBox(aircraft.shape);
  if (symmetry && box.high.Y() <= 0)
    throw Error(ErrorCode::InvalidArgument, "--symmetry: the aircraft has nothing on the side y > 0");
  const double distance = farfieldDistance(farfield, aircraftLength(aircraft.shape));
  const NamedShape boundary = labelledBoundary(farfieldSolid(box, farfield, symmetry, distance), symmetry);
  return cutNamedShape(boundary, aircraft);
}

void generateTetrahedra() {
  callGmsh("meshing the fluid", [] {
    gmsh::option::setNumber("General.AbortOnError", 2);
    // Delaunay: Gmsh 4.8's parallel HXT is many times slower with a size field, and fails on
    // large domains (docs/performance.md).
    gmsh::option::setNumber("Mesh.Algorithm3D", 1);
    gmsh::model::mesh::generate(3);
  });
}

}  // namespace airshape::meshing
