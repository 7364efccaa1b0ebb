#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>

namespace airshape::geometry {

/// Where a closed polygon (the last corner joins the first) crosses itself: the indices of
/// the first corners of two of its sides that cross, or nothing when none do. Sides that
/// only touch (a corner within `tolerance` of the other side, or sides along one line) do
/// not count, nor do sides shorter than `tolerance`. A profile's points outline its curve,
/// so a crossing here is a curve that crosses itself (points given out of order).
std::optional<std::pair<std::size_t, std::size_t>> polygonCrossing(const std::vector<gp_Pnt2d>& corners,
                                                                   double tolerance);

/// Every pair of crossing sides of a closed polygon (by their first corners), as
/// polygonCrossing finds the first.
std::vector<std::pair<std::size_t, std::size_t>> polygonCrossings(const std::vector<gp_Pnt2d>& corners,
                                                                  double tolerance);

/// How far two crossing sides of a polygon (by their first corners) reach through each other:
/// the smallest distance of a side's end from the line of the other side. Moving the points
/// by that much would undo the crossing.
double crossingDepth(const std::vector<gp_Pnt2d>& corners, std::pair<std::size_t, std::size_t> sides);

/// A profile outline may cross itself by this share of its size (the diagonal of its box, about
/// the chord of an airfoil) and still be lofted, with a warning: optimisers write airfoils that
/// zig-zag by a few millionths of the chord at the leading edge, which CAD tools take as given.
constexpr double kToleratedCrossing = 1e-5;

/// A zig-zag: two sides at most this many sides apart along an outline of more than three
/// times as many that cross (points stepping back and forth, as optimisers write them near a
/// leading edge) ...
constexpr std::size_t kZigZagReach = 4;
/// ... may cross by this share of the profile's size and still be lofted, with a warning
/// (sides further apart that cross are points given out of order).
constexpr double kToleratedZigZag = 1e-3;

/// A zig-zag of an outline: its sides from corners `firstSide` and `lastSide` (at most
/// kZigZagReach apart, neither across the outline's closing side) cross at `along` (the share
/// of side `firstSide` from its first corner) by `depth`; the corners between them make a loop.
struct ZigZag {
  std::size_t firstSide = 0, lastSide = 0;
  double along = 0, depth = 0;
};

/// The zig-zags of an outline no deeper than kToleratedZigZag of its size, in order, each
/// loop apart from the next. Interpolated through as given, such a loop's curve may cross
/// itself and the loft's wire with it (BRepCheck: "self intersecting wire").
std::vector<ZigZag> zigZags(const std::vector<gp_Pnt2d>& corners, double tolerance);

/// The points with each zig-zag's loop (its corners firstSide + 1 .. lastSide) replaced by the
/// point where its sides cross: the outline then runs past it without a loop, off the given
/// points by at most the zig-zag's depth.
std::vector<gp_Pnt> withoutZigZags(const std::vector<gp_Pnt>& points, const std::vector<ZigZag>& zigZags);

/// Checks the outline of a profile's points (`xpath`, its point list). Throws Error naming
/// `xpath` when the outline encloses no area (thinner on average than `tolerance`: the points
/// lie on a line) or crosses itself by more than kToleratedCrossing of its size
/// (kToleratedZigZag where the sides are at most kZigZagReach apart), saying which sides cross
/// and by how much: by the corners' places in the file (`placeInFile[k]`, 0-based;
/// the corners' own order when empty), counted from 1. Returns the warning for a crossing
/// within that tolerance (the profile is lofted as given), else nothing. Fewer than three
/// corners are left to the caller.
std::optional<std::string> requireProfileOutline(const std::vector<gp_Pnt2d>& corners, double tolerance,
                                                 const std::vector<int>& placeInFile, const std::string& xpath);

}  // namespace airshape::geometry
