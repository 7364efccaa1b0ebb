#pragma once

#include <string>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// One ribs definition as the schema gives it, and where it lies.
struct RibsDefinition {
  std::string uid;
  std::string xpath;
  std::string componentSegmentUid;
  std::string wingUid;
  const schema::WingRibsDefinitionType* node = nullptr;
  const schema::WingComponentSegmentStructureType* structure = nullptr;  ///< holds its spars
  std::string deviceUid;  ///< the control device whose own structure it is, if any
};

/// The ribs definition with this uID in any model. Throws Error when none has it.
RibsDefinition ribsDefinitionNamed(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
