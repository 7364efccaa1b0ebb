#include "rotor_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"

namespace airshape::rotor {

std::vector<const schema::RotorType*> addressedRotors(const Configuration& configuration) {
  std::vector<const schema::RotorType*> rotors;
  const auto& vehicles = configuration.cpacs().vehicles;
  if (!vehicles || (vehicles->aircraft && !vehicles->aircraft->model.empty())) return rotors;
  if (!vehicles->rotorcraft || vehicles->rotorcraft->model.empty()) return rotors;
  const schema::RotorcraftModelType& model = vehicles->rotorcraft->model[0];
  if (model.rotors)
    for (const auto& rotor : model.rotors->rotor) rotors.push_back(&rotor);
  return rotors;
}

RotorInModel rotorNamed(const Configuration& configuration, const std::string& uid) {
  const auto& vehicles = configuration.cpacs().vehicles;
  if (vehicles && vehicles->rotorcraft)
    for (const auto& model : vehicles->rotorcraft->model)
      if (model.rotors)
        for (const auto& rotor : model.rotors->rotor)
          if (rotor.uID == uid) return {&rotor, &model};
  throw Error(ErrorCode::InvalidArgument, "no rotor with uID '" + uid + "'");
}

}  // namespace airshape::rotor
