#pragma once

#include <vector>

#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/named_shape.h"
#include "spar_list.h"
#include "structure_services.h"

namespace airshape::structure {

class StructureFrame;

/// The surface a spar segment stands in, reaching across its component segment's solid: for
/// each two consecutive spar positions, the plane face through the lines along the wing's up
/// direction (its own z axis) at the positions' points on the chord surface, reaching the
/// frame's reach above and below. Its first and last face are carried the reach beyond their
/// end where the spar ends at the component segment's inner or outer end (eta 0 or 1), or at
/// every end when the wall bounds a region (a fuel tank). The points and `up` are in the global
/// frame.
struct SparWall {
  enum class Ends { CarriedAtComponentSegmentEnds, AlwaysCarried };
  std::vector<gp_Pnt> points;
  std::vector<TopoDS_Face> faces;
  gp_Vec up;
  bool carriedBeforeFirst = false, carriedAfterLast = false;
};
SparWall sparWall(const StructureFrame& frame, const SparSegment& spar, SparWall::Ends ends);

/// The web of a spar segment (QUERY-components §1, `wing_spar`): the part of its wall inside
/// the component segment's solid, reaching the end caps where the spar ends at them. Faces
/// are named "<uID>/web". Throws Error naming the CPACS path of what cannot be built.
NamedShape sparWeb(const Configuration& configuration, const StructureServices& services, const SparSegment& spar);

}  // namespace airshape::structure
