#pragma once

#include <vector>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A component segment with the wing it lies in: where a wing's structure is defined.
struct WingComponentSegment {
  const schema::WingType* wing = nullptr;
  const schema::ComponentSegmentType* componentSegment = nullptr;
};

/// Every component segment of every wing of every model, in document order.
std::vector<WingComponentSegment> everyComponentSegment(const Configuration& configuration);

}  // namespace airshape::structure
