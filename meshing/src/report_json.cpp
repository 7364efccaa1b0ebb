#include <nlohmann/json.hpp>

#include "airshape/meshing/mesher.h"

namespace airshape::meshing {

std::string reportAsJson(const MeshReport& report) {
  nlohmann::json meshes = nlohmann::json::array();
  for (const MeshSummary& summary : report.meshes) {
    nlohmann::json elements = nlohmann::json::object();
    for (const auto& [type, count] : summary.elements) elements[type] = count;
    meshes.push_back({{"name", summary.name},
                      {"nodes", summary.nodes},
                      {"elements", elements},
                      {"worst_quality", summary.worstQuality},
                      {"seconds", summary.seconds}});
  }
  return nlohmann::json{{"meshes", meshes}, {"failures", report.failures}, {"notes", report.notes}}.dump();
}

}  // namespace airshape::meshing
