#include "mesh_lines.h"

#include <algorithm>

#include <BRep_Tool.hxx>
#include <Poly_Polygon3D.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace airshape::exporting {

bool hasLines(const ExportScene& scene) {
  return std::any_of(scene.components.begin(), scene.components.end(), [](const SceneComponent& component) {
    return TopExp_Explorer(component.shape.shape, TopAbs_EDGE, TopAbs_FACE).More();
  });
}

bool hasFaces(const TopoDS_Shape& shape) { return TopExp_Explorer(shape, TopAbs_FACE).More(); }

bool hasFaces(const ExportScene& scene) {
  return std::any_of(scene.components.begin(), scene.components.end(),
                     [](const SceneComponent& component) { return hasFaces(component.shape.shape); });
}

std::vector<std::vector<gp_Pnt>> polylinesOf(const TopoDS_Shape& shape) {
  std::vector<std::vector<gp_Pnt>> lines;
  for (TopExp_Explorer edge(shape, TopAbs_EDGE, TopAbs_FACE); edge.More(); edge.Next()) {
    TopLoc_Location location;
    const Handle(Poly_Polygon3D) polyline = BRep_Tool::Polygon3D(TopoDS::Edge(edge.Current()), location);
    if (polyline.IsNull() || polyline->NbNodes() < 2) continue;
    std::vector<gp_Pnt> line;
    for (int i = 1; i <= polyline->NbNodes(); ++i)
      line.push_back(polyline->Nodes().Value(i).Transformed(location.Transformation()));
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace airshape::exporting
