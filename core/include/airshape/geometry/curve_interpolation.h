#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>

#include "airshape/geometry/bspline_curve.h"

namespace airshape::geometry {

/// Solves for control points so that the curve of `space` passes through `points` (rows)
/// at `parameters`; the number of points must equal the space's pole count.
PoleMatrix interpolatePoles(const KnotVector& space, const std::vector<double>& parameters, const PoleMatrix& points);
/// The same for any number of coordinate columns at once (one factorisation for all).
Eigen::MatrixXd interpolateColumns(const KnotVector& space, const std::vector<double>& parameters,
                                   const Eigen::MatrixXd& values);

/// The B-spline curve of the given degree (lowered to what the point count allows) that
/// passes through `points` at `parameters` (ascending). Knots by averaging; indices in
/// `kinks` (interior points) become knots of full multiplicity, so the curve has corners
/// there. When `closed` is true the first and last point must coincide and the result is
/// a periodic curve, C^(degree-1) everywhere including the seam.
Handle(Geom_BSplineCurve) interpolateCurve(const std::vector<gp_Pnt>& points, const std::vector<double>& parameters,
                                           int degree = 3, bool closed = false, const std::vector<int>& kinks = {});

}  // namespace airshape::geometry
