#pragma once

#include <string>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// One cell of a component segment's upper or lower shell, and where it lies.
struct WingCell {
  std::string uid;
  std::string xpath;
  std::string componentSegmentUid;
  std::string wingUid;
  bool upper = true;  ///< of the upper shell, else of the lower
  const schema::WingCellType* node = nullptr;
  const schema::WingComponentSegmentStructureType* structure = nullptr;  ///< holds its spars and ribs
  std::string deviceUid;  ///< the control device whose own structure it is, if any
};

/// The cell with this uID in any model. Throws Error when none has it.
WingCell wingCellNamed(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
