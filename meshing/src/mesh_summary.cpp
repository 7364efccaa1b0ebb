#include "mesh_summary.h"

#include <algorithm>
#include <cstdio>

#include <gmsh.h>

#include "gmsh_session.h"

namespace airshape::meshing {

namespace {

/// The plural for a summary line of Gmsh's element type name ("Triangle 3" -> "triangles").
std::string pluralOfType(const std::string& gmshName) {
  static const std::vector<std::pair<std::string, std::string>> names = {
      {"Line 2", "lines"},
      {"Line 3", "lines (3 nodes)"},
      {"Triangle 3", "triangles"},
      {"Triangle 6", "triangles (6 nodes)"},
      {"Quadrilateral 4", "quadrilaterals"},
      {"Quadrilateral 8", "quadrilaterals (8 nodes)"},
      {"Tetrahedron 4", "tetrahedra"},
      {"Prism 6", "prisms"},
      {"Tetrahedron 10", "tetrahedra (10 nodes)"}};
  for (const auto& [gmsh, plural] : names)
    if (gmsh == gmshName) return plural;
  return gmshName + " elements";
}

/// The worst inverse condition number of the elements of `dimension`.
double worstQuality(int dimension) {
  double worst = 1;
  callGmsh("measuring the mesh's quality", [&] {
    gmsh::plugin::setNumber("AnalyseMeshQuality", "ICNMeasure", 1);
    gmsh::plugin::setNumber("AnalyseMeshQuality", "JacobianDeterminant", 0);
    gmsh::plugin::setNumber("AnalyseMeshQuality", "CreateView", 1);
    gmsh::plugin::setNumber("AnalyseMeshQuality", "DimensionOfElements", dimension);
    gmsh::plugin::run("AnalyseMeshQuality");
    std::vector<int> views;
    gmsh::view::getTags(views);
    for (int view : views) {
      std::string type;
      std::vector<std::size_t> tags;
      std::vector<std::vector<double>> values;
      double time = 0;
      int components = 0;
      gmsh::view::getModelData(view, 0, type, tags, values, time, components);
      for (const std::vector<double>& value : values)
        if (!value.empty()) worst = std::min(worst, value.front());
      gmsh::view::remove(view);
    }
  });
  return worst;
}

std::string withThousands(std::size_t number) {
  std::string digits = std::to_string(number);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(static_cast<std::size_t>(at), ",");
  return digits;
}

}  // namespace

MeshSummary summaryOfGmshMesh(const std::string& name, const MeshTables& tables) {
  MeshSummary summary;
  summary.name = name;
  summary.nodes = tables.nodeCount();
  int highest = 0;
  for (const ElementBlock& block : tables.blocks) {
    summary.elements.emplace_back(pluralOfType(block.name), block.entity.size());
    highest = std::max(highest, block.dimension);
  }
  summary.worstQuality = highest >= 2 ? worstQuality(highest) : 1;
  return summary;
}

std::string summaryLine(const MeshSummary& summary) {
  std::string line = summary.name + ": " + withThousands(summary.nodes) + " nodes";
  for (const auto& [type, count] : summary.elements) line += ", " + withThousands(count) + " " + type;
  char tail[96];
  std::snprintf(tail, sizeof tail, ", worst quality %.3f, %.1f s", summary.worstQuality, summary.seconds);
  return line + tail;
}

}  // namespace airshape::meshing
