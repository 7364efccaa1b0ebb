#pragma once

#include <optional>
#include <set>
#include <vector>

#include <gp_Pnt.hxx>

#include <Geom_BSplineCurve.hxx>

#include "airshape/geometry/bspline_curve.h"

namespace airshape::geometry {

/// Points a curve must pass through exactly, at given parameters, and for a closed curve
/// the derivatives (1 to seamContinuity) that must agree at the two ends of its range; with
/// `freeSeam` the two ends must also meet (a closed curve whose seam point is not pinned).
struct InterpolationConstraints {
  std::vector<double> parameters;
  PoleMatrix points = PoleMatrix(0, 3);
  int seamContinuity = 0;
  bool freeSeam = false;
  /// Where the seam conditions compare the curve at its start and at its end: at the ends of
  /// its range, or at the current parameter of a sample (an index into the samples), which
  /// parameter corrections move off the range's end, so that the curve's own ends part.
  std::optional<std::size_t> seamStartSample, seamEndSample;
};

/// Where a fit of a list of points compares a closed curve's ends (fitPointsCorrectingParameters):
/// at the ends of its range, or, as the reference library fits approximated body profiles,
/// at the list's first and last point's current parameters (fixed where they are pinned).
enum class SeamAt { RangeEnds, EndPoints };

/// Least-squares approximation: the control points of `space` that minimise the squared
/// distances to `points` (rows) at `parameters`, subject to passing exactly through the
/// constraint points. Solves the constrained normal equations (a KKT system)
///   [NᵀN  Cᵀ] [P]   [NᵀQ]
///   [C    0 ] [λ] = [ D ]
/// Throws Error when the system is singular (too few samples for the control points).
PoleMatrix approximatePoles(const KnotVector& space, const std::vector<double>& parameters, const PoleMatrix& points,
                            const InterpolationConstraints& constraints = {});

/// How far a fitted curve is from its samples: the largest distance of a sample from the
/// curve's point at the sample's parameter, or the root mean square of those distances.
enum class FitError { Largest, RootMeanSquare };

/// A least-squares fit (approximatePoles) whose sample parameters are corrected: after each
/// fit, every sample's parameter moves to the foot of the sample on the curve (Newton's
/// method from its current parameter, at most 10 steps, a step leaving the curve's range
/// ending the search where it began), and the curve is fitted again. The corrections go on
/// while they lower the error by more than a thousandth of it, at most `maxCorrections`
/// times; the last fit is returned (also when the last correction raised the error a little,
/// as the reference library's fit does). The constraints keep their parameters.
Handle(Geom_BSplineCurve)
    fitCorrectingParameters(const KnotVector& space, std::vector<double> parameters, const PoleMatrix& points,
                            const InterpolationConstraints& constraints, FitError measure, int maxCorrections = 10);

/// fitCorrectingParameters on a list of points: those whose indices are `pinned` are passed
/// through exactly at their parameters, the others are the samples whose parameters get
/// corrected; `seam` closes the curve (its seamContinuity and freeSeam; no points of its own),
/// comparing its ends where `seamAt` says.
Handle(Geom_BSplineCurve) fitPointsCorrectingParameters(const KnotVector& space, const std::vector<double>& parameters,
                                                        const std::vector<gp_Pnt>& points, const std::set<int>& pinned,
                                                        FitError measure, const InterpolationConstraints& seam = {},
                                                        int maxCorrections = 10, SeamAt seamAt = SeamAt::RangeEnds);

}  // namespace airshape::geometry
