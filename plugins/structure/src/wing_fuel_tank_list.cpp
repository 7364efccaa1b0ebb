#include "wing_fuel_tank_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/primary_model.h"

namespace airshape::structure {

WingFuelTank wingFuelTankNamed(const Configuration& configuration, const std::string& uid) {
  for (const model::ModelComponents& model : model::everyModel(configuration))
    for (const schema::WingType* wing : model.wings) {
      if (!wing->componentSegments) continue;
      for (const auto& componentSegment : wing->componentSegments->componentSegment) {
        if (!componentSegment.wingFuelTanks) continue;
        for (const auto& tank : componentSegment.wingFuelTanks->wingFuelTank)
          if (tank.uID == uid) return {tank.uID, tank.xpath, componentSegment.uID, wing->uID, &tank};
      }
    }
  throw Error(ErrorCode::InvalidArgument, "no wing fuel tank with uID '" + uid + "'");
}

}  // namespace airshape::structure
