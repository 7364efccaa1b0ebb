#pragma once

#include <string>

#include "airshape/named_shape.h"
#include "airshape/tank/tank_services.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A frame of a fuselage (or of a tank's vessel, found through `tanks` when given) as the line it runs along on the
/// skin (edges, no faces): all round the fuselage in the plane x = positionX for a frame of one position, otherwise
/// where the surface its positions sweep (position_rays.h) meets the skin. Throws Error naming the CPACS path when it
/// cannot be built.
NamedShape frameLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid);

/// A fuselage stringer as the line it runs along on the skin from its first to its last position
/// (edges, no faces; position_rays.h). Throws Error naming the CPACS path when it cannot be built.
NamedShape stringerLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid);

}  // namespace airshape::structure
