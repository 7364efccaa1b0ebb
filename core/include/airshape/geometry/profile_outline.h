#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gp_Pnt2d.hxx>

namespace airshape::geometry {

/// Where a closed polygon (the last corner joins the first) crosses itself: the indices of
/// the first corners of two of its sides that cross, or nothing when none do. Sides that
/// only touch (a corner within `tolerance` of the other side, or sides along one line) do
/// not count, nor do sides shorter than `tolerance`. A profile's points outline its curve,
/// so a crossing here is a curve that crosses itself (points given out of order).
std::optional<std::pair<std::size_t, std::size_t>> polygonCrossing(const std::vector<gp_Pnt2d>& corners,
                                                                   double tolerance);

/// Throws Error naming `xpath` (a profile's point list) when the outline of its points
/// encloses no area (thinner on average than `tolerance`: the points lie on a line) or
/// crosses itself, saying which sides cross: by the corners' places in the file
/// (`placeInFile[k]`, 0-based; the corners' own order when empty), counted from 1. Fewer
/// than three corners are left to the caller.
void requireProfileOutline(const std::vector<gp_Pnt2d>& corners, double tolerance, const std::string& xpath,
                           const std::vector<int>& placeInFile = {});

}  // namespace airshape::geometry
