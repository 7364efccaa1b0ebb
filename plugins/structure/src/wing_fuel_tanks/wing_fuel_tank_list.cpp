#include "wing_fuel_tank_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "component_segments.h"

namespace airshape::structure {

WingFuelTank wingFuelTankNamed(const Configuration& configuration, const std::string& uid) {
  for (const auto& [wing, componentSegment] : everyComponentSegment(configuration)) {
    if (!componentSegment->wingFuelTanks) continue;
    for (const auto& tank : componentSegment->wingFuelTanks->wingFuelTank)
      if (tank.uID == uid) return {tank.uID, tank.xpath, componentSegment->uID, wing->uID, &tank};
  }
  throw Error(ErrorCode::InvalidArgument, "no wing fuel tank with uID '" + uid + "'");
}

}  // namespace airshape::structure
