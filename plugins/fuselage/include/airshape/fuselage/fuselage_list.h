#pragma once

#include <string>
#include <vector>

#include "airshape/model/typed_components.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::fuselage {

/// The node types fuselages are built as.
inline const std::vector<std::string>& fuselageNodeTypes() {
  static const std::vector<std::string> types = {"fuselage"};
  return types;
}

/// The fuselages of a model that can be built (by default the model queries address), in
/// document order.
inline std::vector<schema::FuselageType*> fuselagesOf(const Configuration& configuration,
                                                      std::size_t model = model::kAddressedModel) {
  return model::typedComponents<schema::FuselageType>(configuration, model, fuselageNodeTypes());
}

/// The buildable fuselage with this uID, in whichever model holds it; Error saying why not.
inline schema::FuselageType& fuselageNamed(const Configuration& configuration, const std::string& uid) {
  return model::typedComponentNamed<schema::FuselageType>(configuration, fuselageNodeTypes(), uid, "fuselage");
}

}  // namespace airshape::fuselage
