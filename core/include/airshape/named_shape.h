#pragma once

#include <string>
#include <utility>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape {

/// A component's solid with a name on each of its faces, so that a face can be found again
/// by what it is: "<segment uID>/upper", "<wing uID>/root", "<fuselage uID>/front", ...
/// (docs/wing.md and docs/fuselage.md list the names). The faces are faces of `shape`.
struct NamedShape {
  TopoDS_Shape shape;
  std::vector<std::pair<std::string, TopoDS_Face>> faces;
};

/// Sews named faces (null faces are left out) into one solid whose faces keep their names.
/// Throws Error when they do not close.
NamedShape sewnNamedSolid(const std::vector<std::pair<std::string, TopoDS_Face>>& namedFaces);

}  // namespace airshape
