#pragma once

#include <memory>

#include "airshape/wing/wing_services.h"

namespace airshape::wing {

/// The wing plugin's implementation of its public interface.
std::shared_ptr<const WingServices> makeWingServices();

}  // namespace airshape::wing
