#pragma once

#include <memory>

#include "airshape/controlsurfaces/device_services.h"
#include "airshape/wing/wing_services.h"

namespace airshape::controlsurfaces {

/// The control-surfaces plugin's DeviceServices, answered from its devices' geometry
/// (device_geometry.h) on the wing the wing plugin offers.
std::shared_ptr<const DeviceServices> makeDeviceServices(std::shared_ptr<const wing::WingServices> wing);

}  // namespace airshape::controlsurfaces
