#include "airshape/export/export_scene.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include <BRepBuilderAPI_Copy.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/fused_shape.h"
#include "airshape/graph/parallel_build.h"
#include "airshape/model/symmetry.h"
#include "airshape/parallel_for.h"
#include "posed_components.h"
#include "structural_model.h"

namespace airshape::exporting {

namespace {

using Clock = std::chrono::steady_clock;

/// Indices of the components to export, in build order: those named, or every one a
/// plugin builds that is not inside another (none, when no plugin builds any), and the posed ones.
std::vector<std::size_t> selectedComponents(const Configuration& configuration, const ExportOptions& options,
                                            const std::map<std::string, PosedComponent>& posed) {
  const graph::ComponentGraph& graph = configuration.components();
  std::vector<bool> wanted(graph.components().size(), false);
  // Every component on its own; parts (segments) and what lies inside its parent (devices at
  // rest) are in their parents already, and groups (ComponentLocation::group) in their
  // components.
  if (options.components.empty())
    for (std::size_t index = 0; index < wanted.size(); ++index) {
      const graph::Component& component = graph.components()[index];
      wanted[index] = !component.part && !component.insideParent && !component.group;
    }
  for (const std::string& uid : options.components) {
    const long index = graph.find(uid);
    if (index < 0) throw Error(ErrorCode::InvalidArgument, "no geometric component with uID '" + uid + "'");
    const graph::Component& component = graph.components()[static_cast<std::size_t>(index)];
    if (configuration.shapes().find(component.nodeType) == nullptr)
      throw noShapeBuilt(uid, component.nodeType, configuration.shapes().declined(component.nodeType));
    wanted[static_cast<std::size_t>(index)] = true;
  }
  // Posed parts are written as solids of their own: those named in the poses, and with `all`
  // those of the selected components (all of them when none is selected).
  const auto selectedOrInSelected = [&](const PosedComponent& component) {
    if (options.components.empty() || component.named) return true;
    for (const std::string& uid : component.within)
      if (std::find(options.components.begin(), options.components.end(), uid) != options.components.end()) return true;
    return false;
  };
  for (const auto& [uid, component] : posed)
    if (selectedOrInSelected(component)) wanted[static_cast<std::size_t>(graph.find(uid))] = true;
  std::vector<std::size_t> selected;
  for (std::size_t index : graph.buildOrder())
    if (wanted[index] && configuration.shapes().find(graph.components()[index].nodeType) != nullptr)
      selected.push_back(index);
  return selected;
}

bool hasMirror(const Configuration& configuration, const std::string& uid) {
  return model::resolvedSymmetry(configuration, uid) != "none";
}

/// Builds one component (and its mirrored half with `mirror`) into the configuration's
/// cache; returns why it failed, if it did.
std::optional<std::string> buildComponent(const Configuration& configuration, const std::string& uid, bool mirror) {
  try {
    configuration.shapes().namedShapeOf(configuration, uid);
    if (mirror && hasMirror(configuration, uid)) configuration.shapes().mirroredShapeOf(configuration, uid);
    return std::nullopt;
  } catch (const Error& error) {
    return error.message();
  } catch (const Standard_Failure& failure) {
    return std::string("geometry kernel failure: ") + failure.GetMessageString();
  } catch (const std::exception& error) {
    return error.what();
  }
}

/// Builds the selected components, independent ones in parallel, reporting progress.
/// Returns those that failed, in build order, with why.
std::vector<std::pair<std::size_t, std::string>> buildSelected(const Configuration& configuration,
                                                               const std::vector<std::size_t>& selected,
                                                               const ExportOptions& options, Clock::time_point start) {
  const graph::ComponentGraph& graph = configuration.components();
  std::vector<std::optional<std::string>> failures(graph.components().size());
  std::mutex reporting;
  std::size_t built = 0;
  graph::forEachByDepth(graph, selected, [&](std::size_t index) {
    const std::string& uid = graph.components()[index].uid;
    failures[index] = buildComponent(configuration, uid, options.mirror);
    const std::lock_guard<std::mutex> lock(reporting);
    ++built;
    if (options.progress)
      options.progress({built, selected.size(), std::chrono::duration<double>(Clock::now() - start).count(),
                        (failures[index] ? "failed " : "built ") + uid});
  });
  std::vector<std::pair<std::size_t, std::string>> failed;
  for (std::size_t index : selected)
    if (failures[index]) failed.emplace_back(index, *failures[index]);
  return failed;
}

Error buildFailure(const Configuration& configuration, std::size_t index, const std::string& why) {
  const graph::Component& component = configuration.components().components()[index];
  return Error(ErrorCode::InvalidModel, "component '" + component.uid + "' could not be built: " + why,
               configuration.source(), component.xpath);
}

/// An own copy of a named shape (new topology, shared curves and surfaces), so that
/// triangulating it leaves the cached solid as it is.
SceneComponent copied(const std::string& name, const NamedShape& shape) {
  try {
    BRepBuilderAPI_Copy copy(shape.shape, false, false);
    SceneComponent component{name, {copy.Shape(), {}}, ""};
    for (const auto& [faceName, face] : shape.faces)
      component.shape.faces.emplace_back(faceName, TopoDS::Face(copy.ModifiedShape(face)));
    for (const auto& [lineName, edge] : shape.lines)
      component.shape.lines.emplace_back(lineName, TopoDS::Edge(copy.ModifiedShape(edge)));
    return component;
  } catch (const Standard_Failure& failure) {
    throw Error(ErrorCode::InvalidModel,
                "the solid of '" + name + "' could not be copied for export: " + failure.GetMessageString());
  }
}

/// Says a step after building (`count` components built) on the export's progress, if any.
std::function<void(const std::string&)> stepReporter(const ExportOptions& options, std::size_t count,
                                                     Clock::time_point start) {
  return [&options, count, start](const std::string& what) {
    if (options.progress)
      options.progress({count, count, std::chrono::duration<double>(Clock::now() - start).count(), what});
  };
}

/// A solid of the scene: its name (the uID, or "<uID> (mirrored)"), its component's type.
struct SceneSolid {
  std::string name;
  NamedShape shape;
  std::string type;
};

/// The solids of the selected components that were built, with their mirrored halves on
/// request: moving components posed, those they lie in with their cut-outs.
/// The detailed shape of a component (ComponentShapes::addDetailed), or nothing when it has
/// none or it cannot be built (then `notes` says why).
std::optional<NamedShape> detailedShape(const Configuration& configuration, const graph::Component& component,
                                        std::vector<std::string>& notes) {
  const ShapeBuilder* builder = configuration.shapes().findDetailed(component.nodeType);
  if (builder == nullptr) return std::nullopt;
  try {
    return (*builder)(configuration, component.uid);
  } catch (const Error& error) {
    notes.push_back(component.uid + ": written as built, without its profile: " + error.message() +
                    (error.cpacsPath().empty() ? "" : " (" + error.cpacsPath() + ")"));
  } catch (const Standard_Failure& failure) {
    notes.push_back(component.uid +
                    ": written as built, without its profile: geometry kernel failure: " + failure.GetMessageString());
  }
  return std::nullopt;
}

/// The selected components that host posed ones, each with its moving parts' cut-outs cut
/// out (and posed itself, if it moves), keyed by uID. The cuts are independent Boolean
/// operations: made on every core, so that one component's cut runs beside another's.
std::map<std::string, NamedShape> cutHosts(const Configuration& configuration, const std::vector<std::size_t>& selected,
                                           const std::vector<bool>& failed, const std::set<std::string>& hosts,
                                           const std::map<std::string, PosedComponent>& posed,
                                           const std::function<void(const std::string&)>& step) {
  std::vector<std::string> uids;
  for (std::size_t index : selected)
    if (!failed[index] && hosts.count(configuration.components().components()[index].uid) > 0)
      uids.push_back(configuration.components().components()[index].uid);
  std::vector<NamedShape> shapes(uids.size());
  std::mutex reporting;
  parallelFor(uids.size(), [&](std::size_t index) {
    shapes[index] = posedSolid(configuration, uids[index], posed);
    const std::lock_guard<std::mutex> lock(reporting);
    step("cut its moving parts out of " + uids[index]);
  });
  std::map<std::string, NamedShape> cut;
  for (std::size_t index = 0; index < uids.size(); ++index) cut.emplace(uids[index], std::move(shapes[index]));
  return cut;
}

std::vector<SceneSolid> sceneSolids(const Configuration& configuration, const std::vector<std::size_t>& selected,
                                    const std::vector<bool>& failed, const std::map<std::string, PosedComponent>& posed,
                                    const ExportOptions& options, std::vector<std::string>& notes,
                                    const std::function<void(const std::string&)>& step) {
  std::set<std::string> hosts;  // of a posed component
  for (const auto& [uid, component] : posed) hosts.insert(component.host);
  std::set<std::string> changed = hosts;  // posed, or hosting a posed one
  for (const auto& [uid, component] : posed) changed.insert(uid);
  const std::map<std::string, NamedShape> cut = cutHosts(configuration, selected, failed, hosts, posed, step);
  std::vector<SceneSolid> solids;
  for (std::size_t index : selected) {
    if (failed[index]) continue;
    const graph::Component& component = configuration.components().components()[index];
    const std::string& uid = component.uid;
    const bool asBuilt = changed.count(uid) == 0;
    if (const auto detailed =
            options.profiles && asBuilt ? detailedShape(configuration, component, notes) : std::nullopt) {
      solids.push_back({uid, *detailed, component.typeName});
      if (options.mirror && hasMirror(configuration, uid))
        solids.push_back({uid + " (mirrored)",
                          transformedNamedShape(*detailed, model::mirrorIn(model::resolvedSymmetry(configuration, uid)),
                                                " (mirrored)"),
                          component.typeName});
      continue;
    }
    const auto host = cut.find(uid);
    const NamedShape shape = asBuilt             ? configuration.shapes().namedShapeOf(configuration, uid)
                             : host != cut.end() ? host->second
                                                 : posedSolid(configuration, uid, posed);
    solids.push_back({uid, shape, component.typeName});
    if (!options.mirror || !hasMirror(configuration, uid)) continue;
    const std::string plane = model::resolvedSymmetry(configuration, uid);
    solids.push_back({uid + " (mirrored)",
                      asBuilt ? configuration.shapes().mirroredShapeOf(configuration, uid)
                              : transformedNamedShape(shape, model::mirrorIn(plane), " (mirrored)"),
                      component.typeName});
  }
  return solids;
}

/// The structural models (`export --structure`): their components built first, independent
/// ones in parallel, with progress (a failure is said where the models leave it out).
ExportScene structuralScene(const Configuration& configuration, const ExportOptions& options, Clock::time_point start) {
  const std::vector<std::size_t> components = structuralModelComponents(configuration, options);
  buildSelected(configuration, components, options, start);
  ExportScene scene{std::filesystem::path(configuration.source()).stem().string(), {}, {}, {}};
  const auto step = stepReporter(options, components.size(), start);
  for (const SceneComponent& model : structuralModels(configuration, options, scene.leftOut, step))
    scene.components.push_back(copied(model.name, model.shape));
  return scene;
}

}  // namespace

ExportScene buildScene(const Configuration& configuration, const ExportOptions& options) {
  const Clock::time_point start = Clock::now();
  if (options.structure) return structuralScene(configuration, options, start);
  const std::map<std::string, PosedComponent> posed = resolvePoses(configuration, options.poses);
  const std::vector<std::size_t> selected = selectedComponents(configuration, options, posed);
  ExportScene scene{std::filesystem::path(configuration.source()).stem().string(), {}, {}, {}};
  std::vector<bool> failed(configuration.components().components().size(), false);
  const auto failures = buildSelected(configuration, selected, options, start);
  if (!failures.empty() && !options.skipFailed)
    throw buildFailure(configuration, failures.front().first, failures.front().second);
  for (const auto& [index, why] : failures) {
    failed[index] = true;
    scene.leftOut.push_back(configuration.components().components()[index].uid + ": " + why);
  }

  const auto step = stepReporter(options, selected.size(), start);
  const auto solids = sceneSolids(configuration, selected, failed, posed, options, scene.notes, step);
  if (options.fused) {
    step("fusing");
    std::vector<const NamedShape*> shapes;
    for (const SceneSolid& solid : solids) shapes.push_back(&solid.shape);
    scene.components.push_back(copied(scene.name + " (fused)", fuseNamedShapes(shapes)));
  } else {
    for (const SceneSolid& solid : solids) {
      scene.components.push_back(copied(solid.name, solid.shape));
      scene.components.back().type = solid.type;
    }
  }
  return scene;
}

}  // namespace airshape::exporting
