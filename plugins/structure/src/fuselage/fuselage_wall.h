#pragma once

#include <string>

#include "airshape/named_shape.h"
#include "airshape/tank/tank_services.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A fuselage wall segment (QUERY-components §1, `fuselage_wall`; docs/structure.md): plane
/// strips through its wall positions' base points, extruded along the direction phi about the
/// fuselage's x axis (from 0°: the fuselage's z axis; both ways with doubleSidedExtrusion),
/// the first and last edges turned into the planes of the elements there (flushConnectionStart,
/// flushConnectionEnd), kept inside the fuselage and cut back at its bounding walls (the pieces
/// that hold a base point stay). A base point is (x, y, z) in fuselage coordinates, or (y, z)
/// carried along the fuselage's x axis onto a bulkhead, another wall or a fuselage section.
/// Faces are named "<uID>/wall". Walls of a tank's vessel are positioned in the vessel's frame
/// and kept inside it (through the tank plugin's services, `tanks`; without them such walls
/// name nothing). Throws Error naming the CPACS path of what cannot be built.
NamedShape fuselageWall(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid);

}  // namespace airshape::structure
