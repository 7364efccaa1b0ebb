#pragma once

#include <string>
#include <vector>

#include "airshape/model/typed_components.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::wing {

/// The node types wings are built as: a model's wings, then (in a rotorcraft model) its rotor
/// blades, which the query protocol counts as wings after the model's own.
inline const std::vector<std::string>& wingNodeTypes() {
  static const std::vector<std::string> types = {"wing", "rotorBlade"};
  return types;
}

/// The wings of a model that can be built (by default the model queries address), in the
/// order the query protocol counts them.
inline std::vector<schema::WingType*> wingsOf(const Configuration& configuration,
                                              std::size_t model = model::kAddressedModel) {
  return model::typedComponents<schema::WingType>(configuration, model, wingNodeTypes());
}

/// The buildable wing with this uID, in whichever model holds it; Error saying why not.
inline schema::WingType& wingNamed(const Configuration& configuration, const std::string& uid) {
  return model::typedComponentNamed<schema::WingType>(configuration, wingNodeTypes(), uid, "wing");
}

}  // namespace airshape::wing
