#pragma once

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/named_shape.h"
#include "rib_list.h"
#include "structure_services.h"

namespace airshape::structure {

class StructureFrame;

/// Where one rib lies (wing frame): its point on its reference line (on the chord surface),
/// and the directions of its plane, along the rib from its start to its end and up.
struct RibPlacement {
  gp_Pnt point;
  gp_Vec direction, up;
};

/// The placement of rib `number` (from 1) of a ribs definition, without cutting any rib.
/// Throws Error when the definition has no such rib.
RibPlacement ribPlacement(const Configuration& configuration, const RibsDefinition& ribs, const StructureFrame& frame,
                          long long number);

/// The ribs of a ribs definition (QUERY-components §1, `wing_rib`), each the part inside the
/// component segment's solid of the plane the schema places it in, between its start and end
/// (the leading or trailing edge, or a spar's web): ribs set along a reference line
/// (`ribsPositioning`: the leading edge, the trailing edge or a spar, from a start to an end
/// point, by number or spacing), turned by `ribRotation` about the wing's z axis from its y
/// (or x) axis, tilted by the cross section's x rotation; or one rib from a start to an end
/// point (`ribExplicitPositioning`). Faces are named "<uID>/rib <n>".
/// Throws Error naming the CPACS path of what cannot be built.
NamedShape ribFaces(const Configuration& configuration, const StructureServices& services, const RibsDefinition& ribs);

}  // namespace airshape::structure
