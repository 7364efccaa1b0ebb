#pragma once

#include <string>

#include "airshape/named_shape.h"
#include "airshape/tank/tank_services.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A frame with the cross section of its first position's structural element swept along its
/// line on the skin (skin_lines.h): each sheet of the profile (structural_profile.h) sweeps a
/// surface, named "<uID>/<sheet uID>" (the sheets' mid-surfaces, as a shell model of the frame).
/// The profile's plane at a point of the line: its x along the body's x axis (local y), its y
/// into the body, square to the skin (local z), turned by the alignment's rotationLocX about the
/// line and moved by its translationLocY and translationLocZ. Throws Error naming the CPACS
/// path when there is no cross section to sweep (structural_profile.h) or no line.
NamedShape frameProfile(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid);

/// A stringer with its first position's cross section swept along it as frameProfile does; the
/// line runs along the body's x axis (local x), the profile's x is local y = z × x.
NamedShape stringerProfile(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid);

}  // namespace airshape::structure
