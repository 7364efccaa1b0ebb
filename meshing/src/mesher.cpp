#include "airshape/meshing/mesher.h"

#include <chrono>
#include <map>
#include <set>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <gmsh.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/export/export_scene.h"
#include "face_orientation.h"
#include "fluid_domain.h"
#include "gmsh_model.h"
#include "gmsh_session.h"
#include "labelled_shape.h"
#include "layered_fluid.h"
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

/// A shape to hand to Gmsh: its faces labelled, which groups each face goes in, the length
/// sizes are measured against, and the mesh's name.
struct ShapeToMesh {
  NamedShape shape;
  std::vector<FaceLabel> labels;
  GroupsOfFace groupsOf;
  double length = 0;
  std::string name;
  /// Lines to mesh as beams (frames, stringers): each edge with its group names.
  std::vector<std::pair<TopoDS_Edge, std::vector<std::string>>> lines = {};
};

/// The fused aircraft (its faces in a group per component and per face name), or with a far
/// field the fluid around it (its walls in a group per component, "farfield", "symmetry").
ShapeToMesh aircraftToMesh(const exporting::ExportScene& scene, const MeshOptions& options, const Progress& progress,
                           MeshReport& report) {
  progress("fusing the components");
  const NamedShape aircraft = fusedAircraft(scene, report.notes);
  ShapeToMesh toMesh{aircraft, {}, {}, aircraftLength(aircraft.shape), "surface"};
  if (options.farfield) {
    progress("cutting the aircraft out of the far field");
    toMesh.shape = fluidDomain(aircraft, *options.farfield, options.symmetry);
    toMesh.name = "fluid";
    // OpenFOAM's gmshToFoam refuses a face in two groups: one group per face.
    toMesh.groupsOf = [](const FaceLabel& label) { return std::vector<std::string>{label.component}; };
  } else {
    toMesh.groupsOf = [](const FaceLabel& label) {
      std::vector<std::string> groups{label.component.empty() ? "unnamed" : label.component};
      if (!label.face.empty()) groups.push_back(label.face);
      return groups;
    };
  }
  toMesh.labels = faceLabels(toMesh.shape);
  return toMesh;
}

/// The uID of the structural element (or skin segment) a face of a structural model came from:
/// its name up to the first '/'.
std::string elementOf(const std::string& face) { return face.substr(0, face.find('/')); }

/// The structural models side by side, each face in a group per model ("<uID> structure") and
/// per structural element, each line (frames, stringers) in a group per element and per model
/// ("<uID> structure beams": a beam section for the analyst to give, apart from the shells).
ShapeToMesh structureToMesh(const exporting::ExportScene& scene) {
  if (scene.components.empty())
    throw Error(ErrorCode::InvalidArgument, "no component holds spars or ribs that could be built");
  std::vector<NamedShape> models;
  for (const exporting::SceneComponent& model : scene.components)
    models.push_back(labelledFaces(model.shape.shape, model.name, model.shape.faces));
  std::vector<const NamedShape*> parts;
  for (const NamedShape& model : models) parts.push_back(&model);
  ShapeToMesh toMesh{compoundOfNamedShapes(parts), {}, {}, 0, "structure"};
  for (const exporting::SceneComponent& model : scene.components)
    for (const auto& [uid, edge] : model.shape.lines) toMesh.lines.push_back({edge, {uid, model.name + " beams"}});
  toMesh.labels = faceLabels(toMesh.shape);
  toMesh.length = aircraftLength(toMesh.shape.shape);
  toMesh.groupsOf = [](const FaceLabel& label) {
    std::vector<std::string> groups{label.component};
    if (!label.face.empty()) groups.push_back(elementOf(label.face));
    return groups;
  };
  return toMesh;
}

/// The physical groups of the lines to mesh as beams, by the curves Gmsh took them as.
std::vector<PhysicalGroup> lineGroups(const TopoDS_Shape& shape,
                                      const std::vector<std::pair<TopoDS_Edge, std::vector<std::string>>>& lines,
                                      const ImportedShape& imported) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  std::vector<PhysicalGroup> groups;
  std::map<std::string, std::size_t> byName;
  for (const auto& [edge, names] : lines) {
    const int index = edges.FindIndex(edge);
    if (index <= 0) continue;
    for (const std::string& name : names) {
      const auto [at, added] = byName.emplace(name, groups.size());
      if (added) groups.push_back({1, name, {}});
      groups[at->second].entities.push_back(imported.curves[static_cast<std::size_t>(index - 1)]);
    }
  }
  return groups;
}

/// Quadrilateral shells for FEM: Frontal-Delaunay recombined (Gmsh 4.8's frontal quad
/// algorithm crashes on such skins), 4 nodes or 8 (serendipity: CalculiX's S8).
void askForShells(int order) {
  callGmsh("setting up the shell mesh", [order] {
    gmsh::option::setNumber("Mesh.Algorithm", 6);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.ElementOrder", order);
    gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  });
}

}  // namespace

MeshReport meshConfiguration(const Configuration& configuration, const std::vector<std::string>& outputs,
                             const MeshOptions& given) {
  const Progress progress{given, Clock::now()};
  MeshOptions options = given;
  if (options.scene.structure && (options.farfield || options.symmetry || options.boundaryLayer))
    throw Error(ErrorCode::InvalidArgument,
                "--structure meshes the structure as shells; it takes no --farfield, --symmetry or --boundary-layer");
  if ((options.symmetry || options.boundaryLayer) && !options.farfield) options.farfield = Farfield{};
  if (options.order != 1 && options.order != 2)
    throw Error(ErrorCode::InvalidArgument, "--order: 1 or 2, not " + std::to_string(options.order));
  std::vector<MeshFormat> formats;
  for (const std::string& output : outputs) formats.push_back(meshFormatOfPath(output));

  MeshReport report;
  const exporting::ExportScene scene = sceneToMesh(configuration, options, progress);
  for (const std::string& leftOut : scene.leftOut) {  // "uID: why"
    const std::size_t colon = leftOut.find(": ");
    report.failures.push_back(colon == std::string::npos
                                  ? leftOut
                                  : failureOf(configuration, leftOut.substr(0, colon), leftOut.substr(colon + 2)));
  }
  report.notes = scene.notes;
  const ShapeToMesh toMesh =
      options.scene.structure ? structureToMesh(scene) : aircraftToMesh(scene, options, progress, report);

  GmshSession session(scene.name);
  progress("handing the shape to Gmsh");
  const ImportedShape imported = importIntoGmsh(toMesh.shape.shape);
  std::vector<PhysicalGroup> groups =
      physicalGroups(toMesh.labels, imported, toMesh.groupsOf, options.farfield.has_value());
  for (const PhysicalGroup& group : lineGroups(toMesh.shape.shape, toMesh.lines, imported)) groups.push_back(group);
  addToGmsh(groups);
  const Sizes sizes =
      sizesFor(options, toMesh.length, options.farfield ? farfieldDistance(*options.farfield, toMesh.length) : 0.0);
  setSizeFields(toMesh.shape.shape, toMesh.labels, imported, options, sizes);
  if (options.scene.structure) askForShells(options.order);
  progress("meshing the surfaces");
  const auto failedSurfaces = meshSurfaces(toMesh.labels, imported);
  for (const auto& [uid, why] : failedSurfaces) report.failures.push_back(failureOf(configuration, uid, why));
  const bool layered = options.boundaryLayer && failedSurfaces.empty();
  if (options.farfield && failedSurfaces.empty() && !layered) {
    progress("meshing the fluid");
    generateTetrahedra();
  } else if (options.farfield && !failedSurfaces.empty()) {
    report.failures.push_back("fluid: not meshed, its boundary has surfaces without elements");
  }
  progress("reading the mesh");
  MeshTables tables = meshTablesFromGmsh();
  progress("turning the elements outwards");
  orientLikeFaces(tables, toMesh.shape.shape, imported);
  if (layered) {
    progress("growing the boundary layer and meshing the fluid");
    tables = layeredFluid(tables, *options.boundaryLayer, sizes, report.notes);
  }
  progress("measuring the quality");
  MeshSummary summary = summaryOfGmshMesh(toMesh.name, tables);
  for (std::size_t index = 0; index < outputs.size(); ++index) {
    progress("writing " + outputs[index]);
    writeMesh(tables, outputs[index], formats[index]);
  }
  summary.seconds = progress.seconds();
  report.meshes.push_back(summary);
  return report;
}

}  // namespace airshape::meshing
