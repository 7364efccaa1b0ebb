#pragma once

#include "airshape/controlsurfaces/device_services.h"
#include "airshape/wing/wing_services.h"

namespace airshape::structure {

/// What wing structure is built on: the wing plugin's geometry, and the control-surfaces
/// plugin's device coordinates for the structure a flap, slat or spoiler holds of its own.
struct StructureServices {
  const wing::WingServices& wing;
  const controlsurfaces::DeviceServices& devices;
};

}  // namespace airshape::structure
