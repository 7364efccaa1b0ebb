#include "structural_model.h"

#include <map>
#include <mutex>
#include <numeric>

#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRep_Builder.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/parallel_for.h"

namespace airshape::exporting {

namespace {

/// The structure components by the component they lie in, in build order.
std::map<std::string, std::vector<std::string>> structureByHost(const Configuration& configuration) {
  std::map<std::string, std::vector<std::string>> byHost;
  const graph::ComponentGraph& graph = configuration.components();
  for (std::size_t index : graph.buildOrder()) {
    const graph::Component& component = graph.components()[index];
    if (component.structure && !component.parentUid.empty() &&
        configuration.shapes().find(component.nodeType) != nullptr)
      byHost[component.parentUid].push_back(component.uid);
  }
  return byHost;
}

/// Whether a host was asked for: by its uID or its parent's (naming a component selects the
/// hosts that are its parts), or every host when none is named.
bool wanted(const Configuration& configuration, const std::string& host, const ExportOptions& options) {
  if (options.components.empty()) return true;
  const long index = configuration.components().find(host);
  const std::string parent =
      index < 0 ? std::string() : configuration.components().components()[static_cast<std::size_t>(index)].parentUid;
  for (const std::string& uid : options.components)
    if (uid == host || uid == parent) return true;
  return false;
}

/// A model's host and its parts: the host's shape first, then its built structure, each with its uID.
struct ModelParts {
  std::string host;
  std::vector<const NamedShape*> parts;
  std::vector<std::string> uids;
};

/// The edges of a part on none of its faces (a stiffening line's).
std::vector<TopoDS_Edge> freeEdges(const TopoDS_Shape& part) {
  std::vector<TopoDS_Edge> edges;
  for (TopExp_Explorer edge(part, TopAbs_EDGE, TopAbs_FACE); edge.More(); edge.Next())
    edges.push_back(TopoDS::Edge(edge.Current()));
  return edges;
}

/// The host's faces and its structure's joined by one general fuse: every face split where
/// another meets it, all sharing the edges they meet along, in one shell; the lines of the
/// structure (its stiffening lines) split where they cross faces and each other, on the faces
/// they lie on, beside the shell as `lines` named by their component.
NamedShape joined(const ModelParts& model) {
  BRep_Builder builder;
  TopTools_ListOfShape arguments;
  // Each face an argument of its own: the fuse leaves the faces of one argument as they are
  // among themselves, so faces of one part that only touch along an edge they do not share (a
  // web's pieces on either side of a kink) stayed apart (26 free edges in CPACS_30_D150.xml's
  // model). Faces only: a solid would be split into solids.
  std::vector<std::pair<std::string, TopoDS_Edge>> lines;
  for (std::size_t k = 0; k < model.parts.size(); ++k) {
    for (TopExp_Explorer face(model.parts[k]->shape, TopAbs_FACE); face.More(); face.Next())
      arguments.Append(face.Current());
    for (const TopoDS_Edge& edge : freeEdges(model.parts[k]->shape)) {
      arguments.Append(edge);
      lines.emplace_back(model.uids[k], edge);
    }
  }
  BRepAlgoAPI_BuilderAlgo fuse;
  fuse.SetArguments(arguments);
  fuse.SetRunParallel(true);
  fuse.SetNonDestructive(true);  // models are joined side by side: inputs stay untouched
  // Faces less than 0.01 mm apart are one: in CPACS_30_D250_10.xml a web lies on the wall a
  // cut-out leaves in its host, two faces in one place that CalculiX cannot give a normal to.
  fuse.SetFuzzyValue(1e-5);
  fuse.Build();
  if (!fuse.IsDone() || fuse.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the structure of '" + model.host + "' cannot be joined with its faces");
  NamedShape joinedModel = namedBooleanResult(fuse, model.parts);
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (TopExp_Explorer face(joinedModel.shape, TopAbs_FACE); face.More(); face.Next())
    builder.Add(shell, face.Current());
  TopoDS_Compound withLines;
  builder.MakeCompound(withLines);
  builder.Add(withLines, shell);
  for (const auto& [uid, edge] : lines) {
    const TopTools_ListOfShape& pieces = fuse.Modified(edge);
    if (pieces.IsEmpty()) {
      if (!fuse.IsDeleted(edge)) joinedModel.lines.emplace_back(uid, edge);
      continue;
    }
    for (const TopoDS_Shape& piece : pieces) joinedModel.lines.emplace_back(uid, TopoDS::Edge(piece));
  }
  for (const auto& [uid, edge] : joinedModel.lines) builder.Add(withLines, edge);
  joinedModel.shape = joinedModel.lines.empty() ? TopoDS_Shape(shell) : TopoDS_Shape(withLines);
  return joinedModel;
}

/// The wanted models with their parts, in the order of their hosts; structure that fails to
/// build is left out and said in `leftOut`, a host left with nothing to join is no model.
std::vector<ModelParts> modelsToJoin(const Configuration& configuration, const ExportOptions& options,
                                     std::vector<std::string>& leftOut) {
  std::vector<ModelParts> models;
  for (const auto& [host, structure] : structureByHost(configuration)) {
    if (!wanted(configuration, host, options)) continue;
    ModelParts model{host, {&configuration.shapes().namedShapeOf(configuration, host)}, {host}};
    for (const std::string& uid : structure) {
      try {
        model.parts.push_back(&configuration.shapes().namedShapeOf(configuration, uid));
        model.uids.push_back(uid);
      } catch (const Error& error) {
        leftOut.push_back(uid + ": " + error.message());
      } catch (const Standard_Failure& failure) {
        leftOut.push_back(uid + ": geometry kernel failure: " + failure.GetMessageString());
      }
    }
    if (model.parts.size() >= 2) models.push_back(std::move(model));
  }
  return models;
}

/// The models' indices, the one with the most faces first: joined side by side, a large model
/// started last would leave a core idle while it finishes alone (each fuse keeps both cores
/// busy only in parts).
std::vector<std::size_t> largestFirst(const std::vector<ModelParts>& models) {
  std::vector<std::size_t> faces(models.size(), 0);
  for (std::size_t k = 0; k < models.size(); ++k)
    for (const NamedShape* part : models[k].parts) faces[k] += part->faces.size();
  std::vector<std::size_t> order(models.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return faces[a] > faces[b]; });
  return order;
}

}  // namespace

std::vector<std::size_t> structuralModelComponents(const Configuration& configuration, const ExportOptions& options) {
  const graph::ComponentGraph& graph = configuration.components();
  std::vector<bool> taken(graph.components().size(), false);
  for (const auto& [host, structure] : structureByHost(configuration)) {
    if (!wanted(configuration, host, options)) continue;
    taken[static_cast<std::size_t>(graph.find(host))] = true;
    for (const std::string& uid : structure) taken[static_cast<std::size_t>(graph.find(uid))] = true;
  }
  std::vector<std::size_t> components;
  for (std::size_t index : graph.buildOrder())
    if (taken[index]) components.push_back(index);
  return components;
}

std::vector<SceneComponent> structuralModels(const Configuration& configuration, const ExportOptions& options,
                                             std::vector<std::string>& leftOut,
                                             const std::function<void(const std::string&)>& step) {
  const std::vector<ModelParts> models = modelsToJoin(configuration, options, leftOut);
  const std::vector<std::size_t> order = largestFirst(models);
  std::vector<SceneComponent> joinedModels(models.size());
  std::mutex reporting;
  parallelFor(order.size(), [&](std::size_t k) {
    const ModelParts& model = models[order[k]];
    {
      const std::lock_guard<std::mutex> lock(reporting);
      step("joining the structure of " + model.host + " (" + std::to_string(model.parts.size() - 1) +
           (model.parts.size() == 2 ? " component)" : " components)"));
    }
    joinedModels[order[k]] = {model.host + " structure", joined(model), ""};
  });
  return joinedModels;
}

}  // namespace airshape::exporting
