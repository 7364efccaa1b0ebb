#pragma once

#include <string>
#include <vector>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A component segment with the wing it lies in.
struct WingComponentSegment {
  const schema::WingType* wing = nullptr;
  const schema::ComponentSegmentType* componentSegment = nullptr;
};

/// Every component segment of every wing of every model, in document order.
std::vector<WingComponentSegment> everyComponentSegment(const Configuration& configuration);

/// Where wing structure is defined: a component segment's own structure, or the structure of a
/// control device in it (a flap's, a slat's or a spoiler's: `deviceUid` names the device).
struct StructureHost {
  const schema::WingType* wing = nullptr;
  const schema::ComponentSegmentType* componentSegment = nullptr;
  const schema::WingComponentSegmentStructureType* structure = nullptr;
  std::string deviceUid;  ///< empty for the component segment's own structure
};

/// Every structure of every component segment and of every control device in one (trailing-
/// edge devices, leading-edge devices, spoilers), in document order; hosts without structure are
/// left out.
std::vector<StructureHost> everyStructure(const Configuration& configuration);

}  // namespace airshape::structure
