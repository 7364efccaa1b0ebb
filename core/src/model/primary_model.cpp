#include "airshape/model/primary_model.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/segment_chain.h"

namespace airshape::model {

namespace {

/// Adds the component unless its segments cannot be ordered, which `skipped` then records.
template <class Component>
void addIfChained(Component& component, std::vector<Component*>& list, Problems& skipped) {
  std::vector<SegmentEnds> ends;
  if (component.segments)
    for (const auto& segment : component.segments->segment)
      ends.push_back({segment.fromElementUID, segment.toElementUID});
  try {
    chainOrder(ends);
    list.push_back(&component);
  } catch (const Error& error) {
    skipped.push_back({Problem::Severity::Warning, component.xpath + "/segments",
                       error.message() + "; " + component.uID + " cannot be built and is left out"});
  }
}

template <class Model>
PrimaryModel collect(const Model& model) {
  PrimaryModel result;
  if (model.wings)
    for (auto& wing : model.wings->wing) addIfChained(wing, result.wings, result.skipped);
  if (model.fuselages)
    for (auto& fuselage : model.fuselages->fuselage) addIfChained(fuselage, result.fuselages, result.skipped);
  return result;
}

}  // namespace

PrimaryModel primaryModel(const schema::CpacsType& cpacs) {
  if (!cpacs.vehicles) return {};
  const schema::VehiclesType& vehicles = *cpacs.vehicles;
  if (vehicles.aircraft && !vehicles.aircraft->model.empty()) return collect(vehicles.aircraft->model[0]);
  if (vehicles.rotorcraft && !vehicles.rotorcraft->model.empty()) {
    // Rotor blades are wings (schema type wingType) and are addressed as wings after the model's own.
    const schema::RotorcraftModelType& rotorcraft = vehicles.rotorcraft->model[0];
    PrimaryModel result = collect(rotorcraft);
    if (rotorcraft.rotorBlades)
      for (auto& blade : rotorcraft.rotorBlades->rotorBlade) addIfChained(blade, result.wings, result.skipped);
    return result;
  }
  return {};
}

void throwNotInModel(const Configuration& configuration, const std::string& uid, const std::string& kind) {
  for (const Problem& skipped : primaryModel(configuration).skipped)  // left out on loading: say why
    if (skipped.message.find(uid) != std::string::npos)
      throw Error(ErrorCode::InvalidModel, skipped.message, {}, skipped.xpath);
  throw Error(ErrorCode::InvalidArgument, "no " + kind + " with uID '" + uid + "' in the model");
}

const PrimaryModel& primaryModel(const Configuration& configuration) {
  return *configuration.cache().obtain<PrimaryModel>(
      "primary-model", [&] { return std::make_shared<const PrimaryModel>(primaryModel(configuration.cpacs())); });
}

}  // namespace airshape::model
