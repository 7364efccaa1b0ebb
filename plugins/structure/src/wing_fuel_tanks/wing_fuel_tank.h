#pragma once

#include "airshape/named_shape.h"
#include "structure_services.h"
#include "wing_fuel_tank_list.h"

namespace airshape::structure {

/// The solid of a wing fuel tank: the part of its component segment's solid that the tank's
/// borders enclose. A border is the wall of a spar segment (SparWall, carried beyond both its
/// ends) or the plane of one rib of a ribs definition; consecutive borders meet at the tank's
/// corners, seen along the wing's z axis. When the last and the first border are spars that
/// do not meet (a centre tank between two spars and one rib), the component segment's end
/// nearer to the tank's corners closes it. Faces are named "<uID>/<spar uID>" and
/// "<uID>/<ribs uID>/rib <n>" on the walls, "<uID>/<the wing's face name>" on the skins and
/// end caps. Throws Error naming the CPACS path of what cannot be built.
NamedShape wingFuelTankSolid(const Configuration& configuration, const StructureServices& services,
                             const WingFuelTank& tank);

}  // namespace airshape::structure
