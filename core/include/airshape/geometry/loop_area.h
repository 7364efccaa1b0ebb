#pragma once

#include <optional>
#include <vector>

#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

namespace airshape::geometry {

/// The area closed lines in a plane enclose (a solid's section): each line's own area (Green's
/// theorem, exact per knot span), added where the line lies inside an even number of the
/// others and taken off where inside an odd number (the hole of a ring, an island in it added
/// again). Nothing where the lines cross or touch themselves or each other (a solid passing
/// through itself), which bound no regions one inside another.
std::optional<double> areaInsideLoops(const gp_Pln& plane, const std::vector<TopoDS_Wire>& loops);

}  // namespace airshape::geometry
