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
/// each two consecutive spar positions, the face through the lines along the directions the
/// spar stands in at the positions' points on the chord surface (StructureFrame::
/// uprightAtSparPosition: the wing's z axis, or in a section's plane), reaching the frame's
/// reach above and below: a plane face where both stand alike, else the ruled surface between
/// the two lines (a twisted piece). The wall is carried the reach beyond its first and last
/// position where the spar ends at the component segment's inner or outer end (eta 0 or 1), or
/// at every end when the wall bounds a region (a fuel tank): a plane piece carried on, or beyond
/// a twisted piece a plane piece of its own. Everything is in the global frame.
struct SparWall {
  enum class Ends { CarriedAtComponentSegmentEnds, AlwaysCarried };

  /// One piece of the wall: from one point to the next, the lines through them along `fromUp`
  /// and `toUp` (unit); a plane piece may be carried on beyond either point.
  struct Piece {
    TopoDS_Face face;
    gp_Pnt from, to;
    gp_Vec fromUp, toUp;
    bool carriedBefore = false, carriedAfter = false;

    bool plane() const { return fromUp.IsParallel(toUp, 1e-12); }
    /// The direction of the wall's line at share t from `from` to `to`.
    gp_Vec upAt(double t) const { return (1.0 - t) * fromUp + t * toUp; }
  };

  std::vector<gp_Pnt> points;  ///< the spar positions' points
  std::vector<Piece> pieces;   ///< in order along the spar

  std::vector<TopoDS_Face> faces() const;
};
SparWall sparWall(const StructureFrame& frame, const SparSegment& spar, SparWall::Ends ends);

/// The web of a spar segment (QUERY-components §1, `wing_spar`): the part of its wall inside
/// the component segment's solid, reaching the end caps where the spar ends at them. Faces
/// are named "<uID>/web". Throws Error naming the CPACS path of what cannot be built.
NamedShape sparWeb(const Configuration& configuration, const StructureServices& services, const SparSegment& spar);

}  // namespace airshape::structure
