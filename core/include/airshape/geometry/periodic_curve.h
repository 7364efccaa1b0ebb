#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>

namespace airshape::geometry {

/// A periodic cubic B-spline through dense samples of a closed curve whose seam is smooth
/// in direction but maybe not in speed (common for closed clamped curves). Parameters run
/// over [0, 1] by chord length; `parameters` (on the old curve) are mapped onto the new one.
Handle(Geom_BSplineCurve) periodicCopy(const Geom_BSplineCurve& closed, std::vector<double>& parameters);

/// The parameter of the point of `curve` nearest to `point`, refined by Newton's method
/// from `guess`.
double projectNear(const Geom_BSplineCurve& curve, const gp_Pnt& point, double guess);

}  // namespace airshape::geometry
