#pragma once

#include <vector>

#include "airshape/geometry/bspline_curve.h"

namespace airshape::geometry {

/// Points a curve must pass through exactly, at given parameters, and for a closed curve
/// the derivatives (1 to seamContinuity) that must agree at the two ends of its range.
struct InterpolationConstraints {
  std::vector<double> parameters;
  PoleMatrix points = PoleMatrix(0, 3);
  int seamContinuity = 0;
};

/// Least-squares approximation: the control points of `space` that minimise the squared
/// distances to `points` (rows) at `parameters`, subject to passing exactly through the
/// constraint points. Solves the constrained normal equations (a KKT system)
///   [NᵀN  Cᵀ] [P]   [NᵀQ]
///   [C    0 ] [λ] = [ D ]
/// Throws Error when the system is singular (too few samples for the control points).
PoleMatrix approximatePoles(const KnotVector& space, const std::vector<double>& parameters, const PoleMatrix& points,
                            const InterpolationConstraints& constraints = {});

}  // namespace airshape::geometry
