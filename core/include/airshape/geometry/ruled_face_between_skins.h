#pragma once

#include <optional>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/geometry/ruled_crossing.h"

namespace airshape::geometry {

/// The face of the ruled surface of `lines` (global axes) between a lifting surface's upper and
/// lower skin, from the line at t = 0 to the line at t = 1: a twisted piece of a web, or a plate
/// between webs standing at different angles. Made directly from where the lines meet the
/// skins (ruled_crossing.h): its edges on the skins are curves in the ruled surface's own
/// parameters that follow the crossings within `tolerance`. Nothing when the skins are not what
/// this handles (faces that are not untrimmed B-spline patches, a line that misses a skin or
/// meets it twice): the caller then cuts the surface by a Boolean operation.
std::optional<TopoDS_Face> ruledSectionBetweenSkins(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                                    const RuledLines& lines, double tolerance);

/// The face of the ruled surface of `lines` (rays from inside a body: `lines.rays`) from its base
/// line (s = 0, through the rays' origins) out to where the rays meet `skin`, between the rays
/// at t = 0 and t = 1, made the same way. Nothing where the skin does not allow that.
std::optional<TopoDS_Face> ruledFaceOutToSkin(const TopoDS_Shape& skin, const RuledLines& lines, double tolerance);

}  // namespace airshape::geometry
