#pragma once

#include <string>

#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A fuselage's pressure bulkhead (QUERY-components §1, `pressure_bulkhead`): the plane face
/// the fuselage's skin encloses at the bulkhead's frame. The frame's one frame position gives
/// its station: the plane x = positionX of the fuselage's coordinates. The face is named
/// "<uID>/bulkhead". Throws Error naming the CPACS path of what cannot be built: a frame with
/// several frame positions (a bulkhead bounded by a frame path across the fuselage) is not
/// built yet.
NamedShape pressureBulkhead(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
