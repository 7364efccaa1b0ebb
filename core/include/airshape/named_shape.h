#pragma once

#include <string>
#include <utility>
#include <vector>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/geometry/brep_building.h"

class BRepAlgoAPI_BuilderAlgo;
class gp_Trsf;

namespace airshape {

/// A component's solid with a name on each of its faces, so that a face can be found again
/// by what it is: "<segment uID>/upper", "<uID>/root", "<uID>/front", ...
/// (each plugin's docs list its names). The faces are faces of `shape`.
struct NamedShape {
  TopoDS_Shape shape;
  std::vector<std::pair<std::string, TopoDS_Face>> faces;
  /// Edges of `shape` on no face, named by the component they are (the stiffening lines of
  /// a structural model); empty elsewhere.
  std::vector<std::pair<std::string, TopoDS_Edge>> lines = {};
};

/// Sews named faces (null faces are left out) into one solid whose faces keep their names,
/// turned outwards as `orienting` says (geometry::sewnSolid). Throws Error when they do not
/// close.
NamedShape sewnNamedSolid(const std::vector<std::pair<std::string, TopoDS_Face>>& namedFaces,
                          geometry::Orienting orienting = geometry::Orienting::ByVolume);

/// The result of a Boolean operation (fuse, cut, common) on named shapes, each of its faces
/// named as the input face it came from: a face kept as it was keeps its name, the pieces of
/// a split face inherit it; faces of inputs that name none of their faces stay unnamed.
NamedShape namedBooleanResult(BRepAlgoAPI_BuilderAlgo& operation, const std::vector<const NamedShape*>& inputs);

/// Named shapes side by side as one compound (a group of components),
/// each face keeping its name; one shape is returned as it is.
NamedShape compoundOfNamedShapes(const std::vector<const NamedShape*>& shapes);

/// A transformed copy of a named shape (moved or mirrored by `transformation`), each face
/// named as before plus `suffix`.
NamedShape transformedNamedShape(const NamedShape& shape, const gp_Trsf& transformation,
                                 const std::string& suffix = "");

/// The same for any affine map (CPACS transformations scale non-uniformly): moved rigidly
/// (with a mirror or a uniform scale) where the map is one, else through its matrix, the
/// faces keeping their names either way.
NamedShape transformedNamedShape(const NamedShape& shape, const geometry::Affine3& transformation,
                                 const std::string& suffix = "");

}  // namespace airshape
