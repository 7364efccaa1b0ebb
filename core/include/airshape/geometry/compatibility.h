#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

namespace airshape::geometry {

/// Raises every curve to the highest degree among them and inserts knots until all share
/// one knot vector. The geometry does not change. All curves must span the same parameter
/// range; where periodic and clamped curves mix, the periodic ones are made clamped.
void makeCompatible(std::vector<Handle(Geom_BSplineCurve)>& curves);

/// The same for surfaces, in both parameter directions.
void makeCompatible(std::vector<Handle(Geom_BSplineSurface)>& surfaces);

/// The same in v only (and the degrees in both directions): surfaces to be joined side by side
/// in u keep their own u knots, which the others need not carry.
void makeCompatibleAlongV(std::vector<Handle(Geom_BSplineSurface)>& surfaces);

}  // namespace airshape::geometry
