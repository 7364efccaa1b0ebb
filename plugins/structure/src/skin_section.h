#pragma once

#include <optional>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "skin_crossing.h"

namespace airshape::structure {

/// How closely a traced section follows the skins, as a share of the component segment's size
/// (StructureFrame::reach): 1e-8, a micrometre on a 100 m wing. Tighter tolerances need many
/// more points on the crossings of many-knotted skins, and the structural model's general fuse
/// slows with the edges' poles.
inline constexpr double kTraceTolerance = 1e-8;

/// The face of the plane of `lines` between a wing's upper and lower skin, from one end to the
/// other (skin_crossing.h), made directly from where the plane meets the skins, each end
/// closed by the straight line between the skins' ends there: on the family's line or the
/// border line given, or where an end is open, the plane's section of the component segment's
/// flat end airfoil. Nothing when the skins are not what the direct trace handles,
/// or when they meet at an end; the caller then cuts the face by a Boolean operation.
std::optional<TopoDS_Face> sectionBetweenSkins(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                               const CrossingLines& lines, const CrossingEnd& from,
                                               const CrossingEnd& to, double tolerance);

}  // namespace airshape::structure
