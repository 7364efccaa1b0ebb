#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "airshape/meshing/mesh_format.h"
#include "airshape/meshing/mesh_options.h"

namespace airshape {
class Configuration;
}

namespace airshape::meshing {

/// What one mesh came to.
struct MeshSummary {
  std::string name;  ///< "surface", "fluid", "<uID> structure"
  std::size_t nodes = 0;
  std::vector<std::pair<std::string, std::size_t>> elements;  ///< per type: "triangles", count
  double worstQuality = 0;  ///< Gmsh's inverse condition number of the worst element: 1 ideal, <= 0 inverted
  double seconds = 0;       ///< from the start of meshing to the mesh being written
};

/// "surface: 12,345 nodes, 24,690 triangles, worst quality 0.310, 1.2 s"
std::string summaryLine(const MeshSummary& summary);

/// What `airshape mesh` did: the meshes written, what could not be built or meshed (each
/// "uID: why (CPACS path)"), and notes on what was written otherwise than asked.
struct MeshReport {
  std::vector<MeshSummary> meshes;
  std::vector<std::string> failures;
  std::vector<std::string> notes;
};

/// The report as JSON, for the C API and Python: {"meshes": [{"name", "nodes", "elements":
/// {type: count}, "worst_quality", "seconds"}], "failures": [...], "notes": [...]}.
std::string reportAsJson(const MeshReport& report);

/// Meshes a configuration as `options` say (docs/meshing.md) and writes the mesh to each
/// output, in the format its extension names, each file complete or not at all. A component
/// that cannot be built, or on whose surfaces Gmsh fails, is said in `failures` and the rest
/// is meshed. Throws Error when nothing can be meshed or an output cannot be written.
MeshReport meshConfiguration(const Configuration& configuration, const std::vector<std::string>& outputs,
                             const MeshOptions& options);

}  // namespace airshape::meshing
