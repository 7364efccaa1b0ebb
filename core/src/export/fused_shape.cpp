#include "airshape/export/fused_shape.h"

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"

namespace airshape::exporting {

namespace {

/// Names the faces of the union by the history of the Boolean operation: a face kept
/// as it was keeps its name, the pieces of a split face inherit it.
void nameResultFaces(const std::vector<const NamedShape*>& shapes, BRepAlgoAPI_Fuse& fuse, NamedShape& result) {
  TopTools_IndexedMapOfShape resultFaces;
  TopExp::MapShapes(result.shape, TopAbs_FACE, resultFaces);
  for (const NamedShape* shape : shapes)
    for (const auto& [name, face] : shape->faces) {
      if (fuse.IsDeleted(face)) continue;
      const TopTools_ListOfShape& pieces = fuse.Modified(face);
      if (pieces.IsEmpty()) {
        if (resultFaces.Contains(face)) result.faces.emplace_back(name, face);
        continue;
      }
      for (const TopoDS_Shape& piece : pieces)
        if (resultFaces.Contains(piece)) result.faces.emplace_back(name, TopoDS::Face(piece));
    }
}

}  // namespace

NamedShape fuseNamedShapes(const std::vector<const NamedShape*>& shapes) {
  if (shapes.empty()) throw Error(ErrorCode::InvalidArgument, "nothing to fuse");
  if (shapes.size() == 1) return *shapes.front();
  TopTools_ListOfShape arguments, tools;
  arguments.Append(shapes.front()->shape);
  for (std::size_t i = 1; i < shapes.size(); ++i) tools.Append(shapes[i]->shape);
  BRepAlgoAPI_Fuse fuse;
  fuse.SetArguments(arguments);
  fuse.SetTools(tools);
  fuse.SetRunParallel(true);
  fuse.Build();
  if (!fuse.IsDone() || fuse.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the Boolean union of the components failed");
  NamedShape result{fuse.Shape(), {}};
  nameResultFaces(shapes, fuse, result);
  if (!BRepCheck_Analyzer(result.shape).IsValid())
    throw Error(ErrorCode::InvalidModel, "the Boolean union of the components is not a valid shape (BRepCheck)");
  return result;
}

}  // namespace airshape::exporting
