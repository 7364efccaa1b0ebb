#pragma once

#include "airshape/named_shape.h"
#include "airshape/wing/wing_services.h"
#include "spar_list.h"

namespace airshape::structure {

/// The web of a spar segment (QUERY-components §1, `wing_spar`): between each two consecutive
/// spar positions, the part inside the component segment's solid of the ruled face through
/// the lines along the wing's up direction (its own z axis) at the two positions' points on
/// the chord surface. A position at the component segment's inner or outer end (eta 0 or 1)
/// carries the face beyond that end, so that the web reaches the end cap. Faces are named
/// "<uID>/web". Throws Error naming the CPACS path of what cannot be built.
NamedShape sparWeb(const Configuration& configuration, const wing::WingServices& wing, const SparSegment& spar);

}  // namespace airshape::structure
