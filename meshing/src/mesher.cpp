#include "airshape/meshing/mesher.h"

#include <chrono>
#include <set>

#include <gmsh.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/export/export_scene.h"
#include "face_orientation.h"
#include "fluid_domain.h"
#include "gmsh_model.h"
#include "gmsh_session.h"
#include "labelled_shape.h"
#include "mesh_summary.h"
#include "mesh_tables.h"
#include "mesh_writers.h"
#include "size_fields.h"

namespace airshape::meshing {

namespace {

using Clock = std::chrono::steady_clock;

/// Says a step on the options' progress, if any.
struct Progress {
  const MeshOptions& options;
  Clock::time_point start;
  void operator()(const std::string& step) const {
    if (options.progress) options.progress({std::chrono::duration<double>(Clock::now() - start).count(), step});
  }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
};

/// "uID: why (CPACS path)" for a component, its path from the component graph.
std::string failureOf(const Configuration& configuration, const std::string& uid, const std::string& why) {
  const long index = configuration.components().find(uid);
  const std::string path =
      index < 0 ? "" : configuration.components().components()[static_cast<std::size_t>(index)].xpath;
  return uid + ": " + why + (path.empty() ? "" : " (" + path + ")");
}

/// The export scene of the components to mesh: built as for an export, each failure kept.
exporting::ExportScene sceneToMesh(const Configuration& configuration, const MeshOptions& options,
                                   const Progress& progress) {
  exporting::ExportOptions sceneOptions = options.scene;
  sceneOptions.fused = false;
  sceneOptions.skipFailed = true;
  if (options.symmetry) sceneOptions.mirror = false;  // the half model is the aircraft's side y >= 0
  sceneOptions.progress = [&progress](const exporting::ExportProgress& built) { progress(built.step); };
  return exporting::buildScene(configuration, sceneOptions);
}

/// The first of Gmsh's error messages, or a general word.
std::string gmshError(const std::vector<std::string>& messages) {
  for (const std::string& message : messages)
    if (message.rfind("Error", 0) == 0) return message;
  return "no elements made";
}

/// Meshes the surfaces (Gmsh goes on past a surface it fails on) and returns the components
/// with a surface left without elements, each with Gmsh's error.
std::vector<std::pair<std::string, std::string>> meshSurfaces(const std::vector<FaceLabel>& labels,
                                                              const ImportedShape& imported) {
  callGmsh("meshing the surfaces", [] {
    gmsh::option::setNumber("General.AbortOnError", 0);
    gmsh::model::mesh::generate(2);
  });
  const std::vector<std::string> messages = takeGmshMessages();
  std::vector<std::pair<std::string, std::string>> failed;
  std::set<std::string> said;
  for (std::size_t index = 0; index < labels.size(); ++index) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 2, imported.surfaces[index]);
    const bool meshed = !tags.empty() && !tags.front().empty();
    if (!meshed && said.insert(labels[index].component).second)
      failed.emplace_back(labels[index].component, "Gmsh could not mesh its surface " +
                                                       (labels[index].face.empty() ? "" : labels[index].face + " ") +
                                                       "(" + gmshError(messages) + ")");
  }
  return failed;
}

}  // namespace

MeshReport meshConfiguration(const Configuration& configuration, const std::vector<std::string>& outputs,
                             const MeshOptions& given) {
  const Progress progress{given, Clock::now()};
  MeshOptions options = given;
  if (options.symmetry && !options.farfield) options.farfield = Farfield{};
  std::vector<MeshFormat> formats;
  for (const std::string& output : outputs) formats.push_back(meshFormatOfPath(output));

  MeshReport report;
  const exporting::ExportScene scene = sceneToMesh(configuration, options, progress);
  for (const std::string& leftOut : scene.leftOut) report.failures.push_back(leftOut);
  report.notes = scene.notes;
  progress("fusing the components");
  const NamedShape aircraft = fusedAircraft(scene, report.notes);
  const double length = aircraftLength(aircraft.shape);
  if (options.farfield) progress("cutting the aircraft out of the far field");
  const NamedShape domain = options.farfield ? fluidDomain(aircraft, *options.farfield, options.symmetry) : aircraft;
  const std::vector<FaceLabel> labels = faceLabels(domain);

  GmshSession session(scene.name);
  progress("handing the shape to Gmsh");
  const ImportedShape imported = importIntoGmsh(domain.shape);
  addToGmsh(physicalGroups(labels, imported, !options.farfield, options.farfield.has_value()));
  const Sizes sizes = sizesFor(options, length, options.farfield ? farfieldDistance(*options.farfield, length) : 0.0);
  setSizeFields(domain.shape, labels, imported, options, sizes);
  progress("meshing the surfaces");
  const auto failedSurfaces = meshSurfaces(labels, imported);
  for (const auto& [uid, why] : failedSurfaces) report.failures.push_back(failureOf(configuration, uid, why));
  if (options.farfield && failedSurfaces.empty()) {
    progress("meshing the fluid");
    callGmsh("meshing the fluid", [] {
      gmsh::option::setNumber("General.AbortOnError", 2);
      // Delaunay: Gmsh 4.8's parallel HXT is many times slower with a size field, and fails on
      // large domains (docs/performance.md).
      gmsh::option::setNumber("Mesh.Algorithm3D", 1);
      gmsh::model::mesh::generate(3);
    });
  } else if (options.farfield) {
    report.failures.push_back("fluid: not meshed, its boundary has surfaces without elements");
  }
  progress("reading the mesh");
  MeshTables tables = meshTablesFromGmsh();
  progress("turning the elements outwards");
  orientLikeFaces(tables, domain.shape, imported);
  progress("measuring the quality");
  MeshSummary summary = summaryOfGmshMesh(options.farfield ? "fluid" : "surface", tables);
  for (std::size_t index = 0; index < outputs.size(); ++index) {
    progress("writing " + outputs[index]);
    writeMesh(tables, outputs[index], formats[index]);
  }
  summary.seconds = progress.seconds();
  report.meshes.push_back(summary);
  return report;
}

}  // namespace airshape::meshing
