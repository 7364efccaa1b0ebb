#include "airshape/named_shape.h"

#include "airshape/geometry/brep_building.h"

namespace airshape {

NamedShape sewnNamedSolid(const std::vector<std::pair<std::string, TopoDS_Face>>& namedFaces) {
  std::vector<TopoDS_Face> faces, sewn;
  for (const auto& entry : namedFaces) faces.push_back(entry.second);
  NamedShape result;
  result.shape = geometry::sewnSolid(faces, &sewn);
  for (std::size_t i = 0; i < namedFaces.size(); ++i)
    if (!sewn[i].IsNull()) result.faces.emplace_back(namedFaces[i].first, sewn[i]);
  return result;
}

}  // namespace airshape
