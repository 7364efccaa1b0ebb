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
/// "<uID>/bulkhead". On a frame of several positions at one station, the part of that cross
/// section between the skin and the chord from the frame's first to its last skin point (its
/// positions' rays meet the skin there; docs/structure.md). Throws Error naming the CPACS path of
/// what cannot be built: frames whose positions lie at different stations (riffled bulkheads)
/// are not built yet.
NamedShape pressureBulkhead(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
