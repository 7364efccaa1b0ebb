#pragma once

#include "airshape/query/query_registry.h"

namespace airshape {
class Configuration;
}

namespace airshape::query {

/// The op `intersection_curves`: where the solids of two components meet (a wing–fuselage
/// junction), as polylines: {"uid": A, "other": B, ["other_mirrored": true],
/// ["deflection": metres]} -> [[[x, y, z], ...], ...], one polyline per connected piece of
/// the intersection, its points no farther than `deflection` (default 1 mm) from the
/// exact curve. Two components that do not meet give [].
Json intersectionCurves(Configuration& configuration, const Json& query);

}  // namespace airshape::query
