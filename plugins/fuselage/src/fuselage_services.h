#pragma once

#include <memory>

#include "airshape/fuselage/fuselage_services.h"

namespace airshape::fuselage {

/// This plugin's implementation of its public interface.
std::shared_ptr<const FuselageServices> makeFuselageServices();

}  // namespace airshape::fuselage
