#pragma once

#include <optional>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/geometry/skin_trace.h"

namespace airshape::geometry {

/// How closely a traced section follows the skins, as a share of the component segment's size
/// (StructureFrame::reach): 1e-8, a micrometre on a 100 m span. Tighter tolerances need many
/// more points on the crossings of many-knotted skins, and the structural model's general fuse
/// slows with the edges' poles.
inline constexpr double kTraceTolerance = 1e-8;

/// What closes an open end of a section (where the plane leaves the skins): a straight line
/// between the skins' ends (the plane's section of a flat end cap: a web carried beyond the
/// skins' end), or nothing, the skins meeting there (a plate reaching a sharp leading or
/// trailing edge), or, where they end in straight edges lying in one plane (a flat blunt
/// trailing edge), the straight line across it, and where those edges are skew (a twisted blunt
/// trailing edge, closed by the ruled face between them), the curve where the plane meets
/// that face: a conic, made exactly.
enum class OpenEnds { ClosedStraight, SkinsMeet };

/// The face of the plane of `lines` between a lifting surface's upper and lower skin, from one end to the
/// other (skin_crossing.h), made directly from where the plane meets the skins: each end on a
/// line (of the family, or a border) closed by the straight line between the skins' ends there,
/// an open end as `openEnds` says. Nothing when the skins are not what the direct trace handles;
/// the caller then cuts the face by a Boolean operation.
std::optional<TopoDS_Face> sectionBetweenSkins(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                               const CrossingLines& lines, const CrossingEnd& from,
                                               const CrossingEnd& to, double tolerance, OpenEnds openEnds);

}  // namespace airshape::geometry
