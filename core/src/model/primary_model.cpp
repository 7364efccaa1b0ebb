#include "airshape/model/primary_model.h"

#include <algorithm>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/segment_chain.h"

namespace airshape::model {

namespace {

/// Adds the component unless its segments cannot be ordered, which `skipped` then records.
template <class Component>
void addIfChained(Component& component, std::vector<Component*>& list, ModelComponents& model) {
  std::vector<SegmentEnds> ends;
  if (component.segments)
    for (const auto& segment : component.segments->segment)
      ends.push_back({segment.fromElementUID, segment.toElementUID});
  try {
    chainOrder(ends);
    list.push_back(&component);
  } catch (const Error& error) {
    model.skippedUids.push_back(component.uID);
    model.skipped.push_back({Problem::Severity::Warning, component.xpath + "/segments",
                             error.message() + "; " + component.uID + " cannot be built and is left out"});
  }
}

template <class Model>
ModelComponents collect(const Model& model) {
  ModelComponents result;
  if (model.wings)
    for (auto& wing : model.wings->wing) addIfChained(wing, result.wings, result);
  if (model.fuselages)
    for (auto& fuselage : model.fuselages->fuselage) addIfChained(fuselage, result.fuselages, result);
  return result;
}

/// Rotor blades are wings (schema type wingType) and are addressed as wings after the model's own.
ModelComponents collectRotorcraft(const schema::RotorcraftModelType& rotorcraft) {
  ModelComponents result = collect(rotorcraft);
  if (rotorcraft.rotorBlades)
    for (auto& blade : rotorcraft.rotorBlades->rotorBlade) addIfChained(blade, result.wings, result);
  return result;
}

bool holds(const ModelComponents& model, const std::string& uid) {
  for (const auto* wing : model.wings)
    if (wing->uID == uid) return true;
  for (const auto* fuselage : model.fuselages)
    if (fuselage->uID == uid) return true;
  return false;
}

}  // namespace

std::vector<ModelComponents> everyModel(const schema::CpacsType& cpacs) {
  std::vector<ModelComponents> models;
  if (!cpacs.vehicles) return models;
  const schema::VehiclesType& vehicles = *cpacs.vehicles;
  if (vehicles.aircraft)
    for (const auto& model : vehicles.aircraft->model) models.push_back(collect(model));
  if (vehicles.rotorcraft)
    for (const auto& model : vehicles.rotorcraft->model) models.push_back(collectRotorcraft(model));
  return models;
}

const std::vector<ModelComponents>& everyModel(const Configuration& configuration) {
  return *configuration.cache().obtain<std::vector<ModelComponents>>("every-model", [&] {
    return std::make_shared<const std::vector<ModelComponents>>(everyModel(configuration.cpacs()));
  });
}

ModelComponents primaryModel(const schema::CpacsType& cpacs) {
  std::vector<ModelComponents> models = everyModel(cpacs);
  return models.empty() ? ModelComponents{} : std::move(models.front());
}

const ModelComponents& primaryModel(const Configuration& configuration) {
  static const ModelComponents none;
  const std::vector<ModelComponents>& models = everyModel(configuration);
  return models.empty() ? none : models.front();
}

const ModelComponents& modelHolding(const Configuration& configuration, const std::string& uid) {
  const long index = configuration.components().find(uid);
  if (index < 0) throw Error(ErrorCode::InvalidArgument, "no geometric component with uID '" + uid + "'");
  const std::size_t model = configuration.components().components()[static_cast<std::size_t>(index)].model;
  return everyModel(configuration).at(model);
}

bool leftOut(const Configuration& configuration, const graph::Component& component) {
  const std::vector<std::string>& skipped = everyModel(configuration).at(component.model).skippedUids;
  const graph::ComponentGraph& graph = configuration.components();
  for (const graph::Component* above = &component; above != nullptr;) {
    if (std::find(skipped.begin(), skipped.end(), above->uid) != skipped.end()) return true;
    const long parent = graph.find(above->parentUid);
    above = parent < 0 ? nullptr : &graph.components()[static_cast<std::size_t>(parent)];
  }
  return false;
}

void throwNotInModel(const Configuration& configuration, const ModelComponents& model, const std::string& uid,
                     const std::string& kind) {
  for (const Problem& skipped : model.skipped)  // left out on loading: say why
    if (skipped.message.find(uid) != std::string::npos)
      throw Error(ErrorCode::InvalidModel, skipped.message, {}, skipped.xpath);
  const std::vector<ModelComponents>& models = everyModel(configuration);
  const bool primary = &model == &primaryModel(configuration);
  for (std::size_t other = 0; primary && other < models.size(); ++other)
    if (&models[other] != &model && holds(models[other], uid))
      throw Error(ErrorCode::InvalidArgument, "no " + kind + " with uID '" + uid +
                                                  "' in the first model, which queries address ('" + uid +
                                                  "' is in model " + std::to_string(other + 1) + " of the file)");
  throw Error(ErrorCode::InvalidArgument, "no " + kind + " with uID '" + uid + "' in the model");
}

}  // namespace airshape::model
