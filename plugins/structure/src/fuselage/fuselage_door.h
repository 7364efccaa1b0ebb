#pragma once

#include <string>

#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A cargo or passenger door (fuselage/structure/cargoDoors, paxDoors): the part of the
/// fuselage's skin between its start and end frame and between its start and end stringer (the
/// shorter way round), as faces named `<uid>/door`. Throws Error naming the CPACS path when the
/// door cannot be built.
NamedShape fuselageDoor(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
