#pragma once

#include <optional>

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include "airshape/geometry/ruled_crossing.h"

namespace airshape::geometry {

/// A bilinear surface given by its lines (global axes): the line at t = 0 runs from `a0`
/// towards `b0`, the one at t = 1 from `a1` towards `b1`, s along them (0 at a, 1 at b). The
/// side of a ruled solid between two outlines (a control device's cutter), a wall's strip.
struct RuledSide {
  RuledLines lines;
  Handle(Geom_BSplineSurface) surface;
};

RuledSide ruledSide(const gp_Pnt& a0, const gp_Pnt& b0, const gp_Pnt& a1, const gp_Pnt& b1);

/// What bounds a side's part along its lines: one end of the lines (s = 0 or 1) or where they
/// meet a skin. A skin that whole lines meet twice (a closed body's skin) is met by rays
/// instead: from the lines' points at s = `raysFrom`, along the lines (`raysTowards` +1) or
/// against them (-1); 0 takes the whole lines.
struct SideBound {
  enum class Kind { Start, End, Skin } kind;
  const TopoDS_Shape* skin = nullptr;
  double raysFrom = 0.0;
  int raysTowards = 0;
};

/// The part of a side between two bounds along its lines, from t = 0 to 1, as a face of its
/// bilinear surface, without a Boolean operation: where the lines meet a skin is drawn as a
/// curve in the side's parameters (t, s) within `tolerance` (a length) of the true crossing.
/// Where the bounds meet at an end (within the tolerance) the face narrows to a corner there.
/// A null face where the bounds lie together all along; nothing where a bound cannot be drawn
/// (a line missing the skin, meeting it twice) or the bounds cross.
std::optional<TopoDS_Face> sidePart(const RuledSide& side, const SideBound& low, const SideBound& high,
                                    double tolerance);

}  // namespace airshape::geometry
