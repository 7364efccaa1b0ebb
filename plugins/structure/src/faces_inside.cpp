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

}  // namespace airshape::structure
