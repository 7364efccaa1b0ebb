#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>

namespace airshape::geometry {

/// One family of network curves (all profiles, or all guides) with their crossing
/// parameters, to be brought onto common parameters.
struct CurveFamily {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  std::vector<std::vector<double>> crossings;  ///< per curve, ascending (cyclically for closed curves)
  bool closed = false;
};

/// The family after reparametrisation: every curve on [0, 1], crossing the other family
/// at the same `targets` (one per crossing; for closed curves 0 is the first crossing and
/// the period is [0, 1]). All curves share degree, knots and pole count.
struct ReparametrisedFamily {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  std::vector<double> targets;
  double maxDeviation = 0.0;  ///< largest distance between a new curve and its original, sampled
};

/// Brings a family onto common crossing parameters: for each curve, σ is the cubic
/// B-spline through (target_l, crossing_l), which must be strictly increasing (else
/// Error); the curve f∘σ is then approximated by least squares with exact interpolation at
/// the crossings, with the same number of control points for all curves, raised until
/// every curve is within `tolerance` of f∘σ. Corners (C0 knots) of the inputs stay corners.
ReparametrisedFamily reparametrise(const CurveFamily& family, double tolerance);

}  // namespace airshape::geometry
