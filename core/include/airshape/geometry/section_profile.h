#pragma once

#include <optional>

#include <TopoDS_Shape.hxx>
#include <gp_Pln.hxx>

#include "airshape/geometry/plane_region.h"

namespace airshape::geometry {

/// Where a plane is the plane of one of the skins' sections (the root, the tip, a section
/// between two segments: each skin has an edge lying in it, within `tolerance`): the region
/// inside the lifting surface's profile there, bounded by those two edges and, where they do not meet (a
/// blunt trailing edge), by the straight line between them, which is a ruling of the face
/// closing the lifting surface there. Nothing when the skins have no such edges. A plate lying in a
/// section is this region between its borders: the trace along the lines fails there, as the
/// plane runs along the patches' boundaries.
std::optional<PlaneRegion> profileInPlane(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                          const gp_Pln& plane, double tolerance);

}  // namespace airshape::geometry
