#pragma once

#include <memory>

#include "airshape/tank/tank_services.h"

namespace airshape::tank {

/// The tank plugin's TankServices, answered from its vessels (vessel.h).
std::shared_ptr<const TankServices> makeTankServices();

}  // namespace airshape::tank
