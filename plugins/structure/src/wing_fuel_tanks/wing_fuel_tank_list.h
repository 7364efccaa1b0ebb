#pragma once

#include <string>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// One wing fuel tank of a component segment (`wingFuelTanks/wingFuelTank`), and where it lies.
struct WingFuelTank {
  std::string uid;
  std::string xpath;
  std::string componentSegmentUid;
  std::string wingUid;
  const schema::WingFuelTankType* node = nullptr;
};

/// The wing fuel tank with this uID in any model. Throws Error when none has it.
WingFuelTank wingFuelTankNamed(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
