#pragma once

#include <optional>

#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/geometry/plane_region.h"

namespace airshape::geometry {

/// Regions of a surface's parameter plane, for putting faces of one surface together without
/// a Boolean operation: the (u, v) plane is taken as the plane z = 0 of space (a curve
/// (u(t), v(t)) as the curve (u(t), v(t), 0)), so that plane_region's common applies.
inline const gp_Pln kParameterPlane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));

/// A face's region of its surface's parameter plane: its wire's curves on the surface, run
/// so that the face lies on their left; nothing for a face with holes or an edge without a
/// curve on the surface.
std::optional<PlaneRegion> parameterRegionOf(const TopoDS_Face& face);

/// The face of `surface` bounded as a face of the parameter plane is (its edges' curves on
/// the surface, with curves in space made from them), oriented as `like`; nothing when OCCT
/// cannot make it.
std::optional<TopoDS_Face> faceOnSurface(const Handle(Geom_Surface) & surface, const TopoDS_Face& parameterFace,
                                         const TopoDS_Face& like);

}  // namespace airshape::geometry
