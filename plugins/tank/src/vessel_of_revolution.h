#pragma once

#include <string>

#include "airshape/named_shape.h"
#include "dome_meridian.h"

namespace airshape::tank {

/// A vessel given by design parameters, in its own frame: the front dome from x = 0, a
/// cylinder of radius R and length L, and the front dome mirrored behind it, revolved about
/// the x axis into a solid. Its faces are named "<uid>/front dome", "/cylinder" and
/// "/rear dome" (an isotensoid dome's lid is part of its dome).
NamedShape vesselOfRevolution(const DomeMeridian& dome, double cylinderRadius, double cylinderLength,
                              const std::string& uid);

}  // namespace airshape::tank
