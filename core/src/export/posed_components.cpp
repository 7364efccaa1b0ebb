#include "posed_components.h"

#include <algorithm>
#include <memory>

#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/fused_shape.h"

namespace airshape::exporting {

namespace {

const ComponentMotion* motionOf(const Configuration& configuration, const std::string& uid) {
  const long index = configuration.components().find(uid);
  if (index < 0) return nullptr;
  return configuration.shapes().findMotion(
      configuration.components().components()[static_cast<std::size_t>(index)].nodeType);
}

/// The uIDs of the components a component lies in, nearest first (its parentUID chain).
std::vector<std::string> ancestorsOf(const Configuration& configuration, const std::string& uid) {
  const graph::ComponentGraph& graph = configuration.components();
  std::vector<std::string> ancestors;
  long index = graph.find(uid);
  // A parentUID chain is acyclic (the graph refuses cycles), so this walk ends.
  while (index >= 0 && ancestors.size() <= graph.components().size()) {
    index = graph.find(graph.components()[static_cast<std::size_t>(index)].parentUid);
    if (index >= 0) ancestors.push_back(graph.components()[static_cast<std::size_t>(index)].uid);
  }
  return ancestors;
}

/// An exported component on its own: not a part of another (a component segment) and not
/// inside one (a device).
bool standsAlone(const Configuration& configuration, const std::string& uid) {
  const graph::Component& component =
      configuration.components().components()[static_cast<std::size_t>(configuration.components().find(uid))];
  return !component.part && !component.insideParent;
}

double parameterOf(const Configuration& configuration, const ComponentMotion& motion, const std::string& uid,
                   const Pose& pose) {
  if (pose.at == Pose::At::Parameter) return pose.parameter;
  const auto [first, last] = motion.range(configuration, uid);
  return pose.at == Pose::At::Minimum ? std::min(first, last) : std::max(first, last);
}

/// A cut-out's solids each on its own with its faces (a device's cutter and the cut-out of its
/// skins overlap: one argument of a Boolean operation must not overlap itself).
void addSolidsOf(const NamedShape& cutOut, std::vector<NamedShape>& solids) {
  for (TopExp_Explorer solid(cutOut.shape, TopAbs_SOLID); solid.More(); solid.Next()) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid.Current(), TopAbs_FACE, faces);
    NamedShape part{solid.Current(), {}};
    for (const auto& [name, face] : cutOut.faces)
      if (faces.Contains(face)) part.faces.emplace_back(name, face);
    solids.push_back(std::move(part));
  }
}

/// Every component posed with its own motion: "all" first, then those named on their own.
std::map<std::string, PosedComponent> ownPoses(const Configuration& configuration, const std::vector<Pose>& poses) {
  const graph::ComponentGraph& graph = configuration.components();
  std::map<std::string, PosedComponent> posed;
  auto pose = [&](const std::string& uid, const Pose& at) {
    const ComponentMotion& motion = *motionOf(configuration, uid);
    const double parameter = parameterOf(configuration, motion, uid, at);
    posed[uid] = {uid, parameter, motion.at(configuration, uid, parameter), {}, {}, at.uid != "all"};
  };
  for (const Pose& at : poses)
    if (at.uid == "all")
      for (const graph::Component& component : graph.components())
        if (motionOf(configuration, component.uid) != nullptr) pose(component.uid, at);
  for (const Pose& at : poses) {
    if (at.uid == "all") continue;
    if (motionOf(configuration, at.uid) == nullptr)
      throw Error(ErrorCode::InvalidArgument, "--deflect: '" + at.uid + "' names no moving component");
    pose(at.uid, at);
  }
  return posed;
}

/// A component with the cut-outs of the moving parts it hosts (`guests`) cut out of it: the
/// cut-outs fused into one tool first, then one cut. (Cut by them as several tools at once,
/// OCCT 7.6 goes wrong where they overlap one another: the main lifting surface of
/// CPACS_30_aircraft_flaps.xml, whose devices overlap, lost 0.56 m³ where it loses 1.97, by the
/// fused tool as by the cut-outs of one group of devices and then the other's in turn.)
NamedShape withCutOuts(const Configuration& configuration, const std::string& uid,
                       const std::vector<std::string>& guests) {
  const NamedShape& built = configuration.shapes().namedShapeOf(configuration, uid);
  std::vector<NamedShape> solids;
  for (const std::string& moving : guests)
    addSolidsOf(motionOf(configuration, moving)->cutOut(configuration, moving), solids);
  if (solids.empty()) return built;
  std::vector<const NamedShape*> parts;
  for (const NamedShape& solid : solids) parts.push_back(&solid);
  NamedShape tool;
  try {
    tool = fuseNamedShapes(parts);
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, "the cut-outs of the moving parts of '" + uid + "' cannot be joined");
  }
  try {
    return cutNamedShape(built, tool);
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, "the cut-outs of its moving parts could not be cut out of '" + uid + "'");
  }
}

}  // namespace

std::map<std::string, PosedComponent> resolvePoses(const Configuration& configuration, const std::vector<Pose>& poses) {
  std::map<std::string, PosedComponent> posed = ownPoses(configuration, poses);
  std::map<std::string, gp_Trsf> own;
  for (const auto& [uid, component] : posed) own[uid] = component.motion;
  for (auto& [uid, component] : posed) {
    component.within = ancestorsOf(configuration, uid);
    for (const std::string& ancestor : component.within) {
      const auto moving = own.find(ancestor);
      if (moving != own.end()) {
        component.motion.PreMultiply(moving->second);
        if (component.host.empty()) component.host = ancestor;
      } else if (component.host.empty() && standsAlone(configuration, ancestor)) {
        component.host = ancestor;
      }
    }
  }
  return posed;
}

NamedShape posedSolid(const Configuration& configuration, const std::string& uid,
                      const std::map<std::string, PosedComponent>& posed) {
  std::vector<std::string> guests;
  std::string key = "cut-outs of " + uid + " for";
  for (const auto& [moving, component] : posed)
    if (component.host == uid) {
      guests.push_back(moving);
      key += " " + moving;
    }
  // The cut-outs lie where the parts are at rest, so the cut is the same whatever their
  // deflections: kept for the configuration (under a whole-model key, which any edit forgets),
  // a further export at other deflections moves the parts and reuses it (0.8 s of
  // CPACS_30_aircraft_flaps.xml's main lifting surface).
  const NamedShape solid = guests.empty()
                               ? withCutOuts(configuration, uid, guests)
                               : *configuration.cache().obtainForWholeModel<NamedShape>(key, [&] {
                                   return std::make_shared<const NamedShape>(withCutOuts(configuration, uid, guests));
                                 });
  const auto moving = posed.find(uid);
  return moving == posed.end() ? solid : transformedNamedShape(solid, moving->second.motion);
}

}  // namespace airshape::exporting
