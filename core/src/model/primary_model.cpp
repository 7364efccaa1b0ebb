#include "airshape/model/primary_model.h"

namespace airshape::model {

namespace {

template <class Model>
PrimaryModel collect(const Model& model) {
  PrimaryModel result;
  if (model.wings)
    for (auto& wing : model.wings->wing) result.wings.push_back(&wing);
  if (model.fuselages)
    for (auto& fuselage : model.fuselages->fuselage) result.fuselages.push_back(&fuselage);
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
      for (auto& blade : rotorcraft.rotorBlades->rotorBlade) result.wings.push_back(&blade);
    return result;
  }
  return {};
}

}  // namespace airshape::model
