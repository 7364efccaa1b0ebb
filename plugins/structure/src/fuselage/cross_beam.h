#pragma once

#include <string>

#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A cargo or passenger cross beam as its axis (the reference library's one-dimensional
/// geometry; docs/structure.md): the line across the fuselage at height positionZ (fuselage
/// coordinates) in its frame's station plane, from skin to skin. An edge shape, no faces.
/// Throws Error naming the CPACS path of what cannot be built.
NamedShape crossBeam(const Configuration& configuration, const std::string& uid);

/// A cargo or passenger cross-beam strut as its axis: from its cross beam at positionYAtCrossBeam
/// to the fuselage's skin at its frame's station, leaving the beam at angleX about the
/// fuselage's x axis (90°: straight down; less leans towards −y). An edge shape, no faces.
NamedShape crossBeamStrut(const Configuration& configuration, const std::string& uid);

/// A long floor beam as its axis: straight lines through its positions, each on its cross beam
/// at positionY. An edge shape, no faces. Throws Error naming the position that lies beyond its
/// cross beam's ends.
NamedShape longFloorBeam(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
