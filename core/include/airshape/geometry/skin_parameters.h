#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>

namespace airshape::geometry {

/// The parameters at which a skin lofted through curves (inner to outer) passes through each
/// of them, in [0, 1], as the reference library's loft assigns them: the curves are made
/// compatible (raised to a common degree, given the union of their knots), and for each row of
/// corresponding poles the centripetal parameters (cumulative square roots of the distances
/// between neighbours, normalised) are averaged over all rows. Contour coordinates along the
/// span are these parameters (docs/structure.md).
std::vector<double> skinParameters(const std::vector<Handle(Geom_BSplineCurve)>& curves);

}  // namespace airshape::geometry
