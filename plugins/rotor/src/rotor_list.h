#pragma once

#include <string>
#include <vector>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::rotor {

/// The rotors the queries address: those of the model the queries address (QUERY.md: the
/// first aircraft model, else the first rotorcraft model; aircraft models hold no rotors).
std::vector<const schema::RotorType*> addressedRotors(const Configuration& configuration);

/// The rotor with this uID in any rotorcraft model, and the model holding it. Throws Error
/// when none has it.
struct RotorInModel {
  const schema::RotorType* rotor = nullptr;
  const schema::RotorcraftModelType* model = nullptr;
};
RotorInModel rotorNamed(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::rotor
