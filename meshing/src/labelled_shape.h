#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "airshape/named_shape.h"

namespace airshape::exporting {
struct ExportScene;
}

namespace airshape::meshing {

/// Where a face of the shape to mesh came from: its component's uID (a mirrored half's under
/// its component's uID; "farfield" and "symmetry" for a CFD domain's boundary) and its name
/// there ("W1_Seg1/upper"; empty where the component names none).
struct FaceLabel {
  std::string component;
  std::string face;
};

/// A shape's faces labelled while it goes through Boolean operations: the faces of a
/// NamedShape named "<component>\x1f<face>" (namedBooleanResult carries the names over).
NamedShape labelledFaces(const TopoDS_Shape& shape, const std::string& component,
                         const std::vector<std::pair<std::string, TopoDS_Face>>& names = {});

/// The labels of a shape's faces in the order TopExp::MapShapes lists them (the order in which
/// Gmsh numbers the faces it imports); a face without a label gets an empty one.
std::vector<FaceLabel> faceLabels(const NamedShape& labelled);

/// The solids of the scene fused into one shape, its faces labelled with their component and
/// name. Components without a solid (lines, sheets) are left out with a line in `notes`.
/// Throws Error when the union fails or no component has a solid.
NamedShape fusedAircraft(const exporting::ExportScene& scene, std::vector<std::string>& notes);

}  // namespace airshape::meshing
