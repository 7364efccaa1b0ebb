#pragma once

#include <optional>

#include <TopoDS_Shape.hxx>
#include <gp_Pln.hxx>

#include "airshape/geometry/plane_region.h"

namespace airshape::geometry {

/// Where a plane crosses a solid whose faces are planes or ruled B-spline faces (the simple
/// solid that cuts a control device out of its host): the region of the plane inside the
/// solid. On a ruled face each ruling meets the plane in one point, found in closed form; the
/// curve through those points is kept within `tolerance` (a length). Nothing where a face is
/// of another kind, the plane runs along a ruling or lies in a face, or the pieces do not
/// close into loops.
std::optional<PlaneRegion> ruledSolidSection(const TopoDS_Shape& solid, const gp_Pln& plane, double tolerance);

}  // namespace airshape::geometry
