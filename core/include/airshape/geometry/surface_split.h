#pragma once

#include <vector>

#include <Geom_BSplineSurface.hxx>

namespace airshape::geometry {

/// The parts of a surface between consecutive `sites` in v (increasing, inside its v range),
/// each carrying only its own poles and knots, its points at the same parameters as on the
/// surface: what Geom_BSplineSurface::Segment gives per part, but from one knot insertion for
/// all parts instead of a copy of the whole surface per part (linear, not quadratic, in the
/// number of parts). Surfaces periodic in v are segmented part by part.
std::vector<Handle(Geom_BSplineSurface)> splitAlongV(const Geom_BSplineSurface& surface,
                                                     const std::vector<double>& sites);

}  // namespace airshape::geometry
