#include "faces_inside.h"

#include <BRepAlgoAPI_Common.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"

namespace airshape::structure {

std::vector<TopoDS_Face> facesInside(const TopoDS_Shape& faces, const TopoDS_Shape& solid) {
  TopTools_ListOfShape arguments, tools;
  arguments.Append(faces);
  tools.Append(solid);
  BRepAlgoAPI_Common common;
  common.SetArguments(arguments);
  common.SetTools(tools);
  common.SetRunParallel(true);
  common.SetNonDestructive(true);  // the solid is shared, cached geometry
  common.Build();
  if (!common.IsDone() || common.HasErrors()) throw Error(ErrorCode::InvalidModel, "the Boolean common failed");
  std::vector<TopoDS_Face> inside;
  for (TopExp_Explorer face(common.Shape(), TopAbs_FACE); face.More(); face.Next())
    inside.push_back(TopoDS::Face(face.Current()));
  return inside;
}

std::vector<std::vector<TopoDS_Face>> facesInsideEach(const std::vector<TopoDS_Face>& faces,
                                                      const TopoDS_Shape& solid) {
  TopTools_ListOfShape arguments, tools;
  for (const TopoDS_Face& face : faces) arguments.Append(face);
  tools.Append(solid);
  BRepAlgoAPI_Common common;
  common.SetArguments(arguments);
  common.SetTools(tools);
  common.SetRunParallel(true);
  common.SetNonDestructive(true);  // the solid is shared, cached geometry
  common.Build();
  if (!common.IsDone() || common.HasErrors()) throw Error(ErrorCode::InvalidModel, "the Boolean common failed");
  std::vector<std::vector<TopoDS_Face>> inside;
  for (const TopoDS_Face& face : faces) {
    std::vector<TopoDS_Face> parts;
    for (const TopoDS_Shape& part : common.Modified(face)) parts.push_back(TopoDS::Face(part));
    if (parts.empty() && !common.IsDeleted(face)) parts.push_back(face);  // wholly inside, unchanged
    inside.push_back(parts);
  }
  return inside;
}

}  // namespace airshape::structure
