#pragma once

#include <vector>

#include <Eigen/Dense>
#include <Geom_BSplineCurve.hxx>

namespace airshape::geometry {

/// Profiles and guides that cross each other once per pair, sorted: guide l meets profile k
/// at profile parameter profileParameters(k, l) and guide parameter guideParameters(k, l),
/// both ascending along their curve, with profile 0 and guide 0 at the network's corner.
struct CurveNetwork {
  std::vector<Handle(Geom_BSplineCurve)> profiles;
  std::vector<Handle(Geom_BSplineCurve)> guides;
  Eigen::MatrixXd profileParameters;  ///< K x L
  Eigen::MatrixXd guideParameters;    ///< K x L
  /// All profiles are closed and smooth across their seam: the surface is periodic in u.
  /// (Closed profiles with a corner at the seam, such as sharp trailing edges, are treated
  /// as open curves that start and end there.)
  bool profilesClosed = false;
  bool guidesClosed = false;  ///< the same for the guides and v
};

/// Where the curves of a network cross when the caller knows it (profile k meets guide l at
/// profileParameters(k, l) and guideParameters(k, l), in input order): no search needed.
struct KnownCrossings {
  Eigen::MatrixXd profileParameters;
  Eigen::MatrixXd guideParameters;
};

/// Intersects every profile with every guide (or takes the `known` crossings, checking
/// their gaps) and sorts the network: drops a curve that
/// repeats another (the seam curve of a closed network, given twice), reverses the curves
/// that run against the others and orders profiles along the guides and guides along the
/// profiles. `tolerance` is the largest gap (in model units) a crossing may have. Throws
/// Error naming both curves and the gap when a guide misses a profile, and when the
/// network cannot be ordered.
CurveNetwork buildCurveNetwork(std::vector<Handle(Geom_BSplineCurve)> profiles,
                               std::vector<Handle(Geom_BSplineCurve)> guides, double tolerance,
                               const KnownCrossings* known = nullptr);

}  // namespace airshape::geometry
