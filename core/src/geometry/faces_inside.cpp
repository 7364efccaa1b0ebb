#include "airshape/geometry/faces_inside.h"

#include <memory>

#include <BRepAlgoAPI_Common.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "airshape/geometry/outer_wires_apart.h"

namespace airshape::geometry {

namespace {

/// The Boolean common of the arguments with the solid, built; throws Error when it fails.
std::unique_ptr<BRepAlgoAPI_Common> commonWith(const TopTools_ListOfShape& arguments, const TopoDS_Shape& solid) {
  TopTools_ListOfShape tools;
  tools.Append(solid);
  auto common = std::make_unique<BRepAlgoAPI_Common>();
  common->SetArguments(arguments);
  common->SetTools(tools);
  common->SetRunParallel(true);
  common->SetNonDestructive(true);  // the solid is shared, cached geometry
  common->Build();
  if (!common->IsDone() || common->HasErrors()) throw Error(ErrorCode::InvalidModel, "the Boolean common failed");
  return common;
}

}  // namespace

std::vector<TopoDS_Face> facesInside(const TopoDS_Shape& faces, const TopoDS_Shape& solid) {
  TopTools_ListOfShape arguments;
  arguments.Append(faces);
  const auto common = commonWith(arguments, solid);
  std::vector<TopoDS_Face> inside;
  for (TopExp_Explorer face(common->Shape(), TopAbs_FACE); face.More(); face.Next())
    for (const TopoDS_Face& part : outerWiresApart(TopoDS::Face(face.Current()))) inside.push_back(part);
  return inside;
}

std::vector<std::vector<TopoDS_Face>> facesInsideEach(const std::vector<TopoDS_Face>& faces,
                                                      const TopoDS_Shape& solid) {
  TopTools_ListOfShape arguments;
  for (const TopoDS_Face& face : faces) arguments.Append(face);
  const auto common = commonWith(arguments, solid);
  std::vector<std::vector<TopoDS_Face>> inside;
  for (const TopoDS_Face& face : faces) {
    std::vector<TopoDS_Face> parts;
    for (const TopoDS_Shape& part : common->Modified(face))
      for (const TopoDS_Face& apart : outerWiresApart(TopoDS::Face(part))) parts.push_back(apart);
    if (parts.empty() && !common->IsDeleted(face)) parts.push_back(face);  // wholly inside, unchanged
    inside.push_back(parts);
  }
  return inside;
}

std::vector<std::vector<TopoDS_Face>> facesInsideEach(
    const std::vector<TopoDS_Face>& faces, const std::function<const TopoDS_Shape&()>& solid,
    const std::function<std::optional<std::vector<TopoDS_Face>>(std::size_t index)>& direct) {
  std::vector<std::vector<TopoDS_Face>> pieces(faces.size());
  std::vector<TopoDS_Face> toCut;
  std::vector<std::size_t> cutIndices;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (std::optional<std::vector<TopoDS_Face>> made = direct(i)) {
      pieces[i] = std::move(*made);
    } else {
      toCut.push_back(faces[i]);
      cutIndices.push_back(i);
    }
  }
  if (toCut.empty()) return pieces;
  const std::vector<std::vector<TopoDS_Face>> cut = facesInsideEach(toCut, solid());
  for (std::size_t k = 0; k < cut.size(); ++k) pieces[cutIndices[k]] = cut[k];
  return pieces;
}

}  // namespace airshape::geometry
