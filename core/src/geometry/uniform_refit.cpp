#include "airshape/geometry/uniform_refit.h"

#include <algorithm>
#include <cmath>

#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_approximation.h"

namespace airshape::geometry {

namespace {

constexpr int kDegree = 3;
constexpr int kFewestSpans = 8;
constexpr int kFewestSamples = 101;
constexpr double kCornerAngle = 6.0 * M_PI / 180.0;
constexpr double kKnotOnEnd = 1e-12;
constexpr double kKnotSnap = 1e-4;  ///< a corner this close to a uniform knot sits on that knot

/// Spans of the curve counting the point parameters as knots too: a measure of how much
/// detail the curve carries.
int detailSpans(const Geom_BSplineCurve& curve, const std::vector<double>& pointParameters) {
  std::vector<std::pair<double, int>> interior;
  for (int i = 2; i < curve.NbKnots(); ++i) interior.emplace_back(curve.Knot(i), curve.Multiplicity(i));
  for (double t : pointParameters) {
    if (t <= curve.FirstParameter() + kKnotOnEnd || t >= curve.LastParameter() - kKnotOnEnd) continue;
    const bool known = std::any_of(interior.begin(), interior.end(),
                                   [t](const auto& knot) { return std::abs(knot.first - t) <= kKnotOnEnd; });
    if (!known) interior.emplace_back(t, 1);
  }
  int spans = 1;
  for (const auto& knot : interior) spans += knot.second;
  return spans;
}

/// Interior knots where the curve has a corner.
std::vector<double> cornerParameters(const Geom_BSplineCurve& curve) {
  constexpr double kStep = 1e-8;
  std::vector<double> corners;
  for (int i = 2; i < curve.NbKnots(); ++i) {
    if (curve.Multiplicity(i) < curve.Degree()) continue;
    const double t = curve.Knot(i);
    const gp_Vec before = curve.DN(t - kStep, 1), after = curve.DN(t + kStep, 1);
    if (before.Magnitude() > 0.0 && after.Magnitude() > 0.0 && before.Angle(after) > kCornerAngle) corners.push_back(t);
  }
  return corners;
}

/// Clamped cubic knots with `spans` equal spans, plus a full-multiplicity knot at each corner.
KnotVector uniformSpaceWithCorners(double first, double last, int spans, const std::vector<double>& corners) {
  KnotVector space;
  space.degree = kDegree;
  for (int i = 0; i <= spans; ++i) {
    space.knots.push_back(first + (last - first) * i / spans);
    space.multiplicities.push_back(i == 0 || i == spans ? kDegree + 1 : 1);
  }
  for (double corner : corners) {
    const auto near = std::find_if(space.knots.begin(), space.knots.end(),
                                   [corner](double knot) { return std::abs(knot - corner) < kKnotSnap; });
    if (near != space.knots.end()) {
      space.multiplicities[static_cast<std::size_t>(near - space.knots.begin())] =
          std::max(space.multiplicities[static_cast<std::size_t>(near - space.knots.begin())], kDegree);
      continue;
    }
    const auto at = std::upper_bound(space.knots.begin(), space.knots.end(), corner);
    space.multiplicities.insert(space.multiplicities.begin() + (at - space.knots.begin()), kDegree);
    space.knots.insert(at, corner);
  }
  return space;
}

}  // namespace

Handle(Geom_BSplineCurve)
    refitOnUniformSpans(const Geom_BSplineCurve& curve, const std::vector<double>& pointParameters) {
  const double first = curve.FirstParameter(), last = curve.LastParameter();
  const int spans =
      std::max(kFewestSpans, 1 << static_cast<int>(std::floor(std::log2(detailSpans(curve, pointParameters)))));
  const std::vector<double> corners = cornerParameters(curve);
  const KnotVector space = uniformSpaceWithCorners(first, last, spans, corners);

  // Samples: evenly spaced, plus the corners; the ends and corners are kept exactly.
  const int sampleCount = std::max(kFewestSamples, 2 * (spans + kDegree));
  std::vector<double> samples;
  for (int i = 0; i < sampleCount; ++i) samples.push_back(first + (last - first) * i / (sampleCount - 1));
  InterpolationConstraints constraints;
  std::vector<double> kept = {first, last};
  kept.insert(kept.end(), corners.begin(), corners.end());
  std::vector<double> fitted;
  for (double t : samples)
    if (std::none_of(kept.begin(), kept.end(), [t](double k) { return std::abs(k - t) <= kKnotOnEnd; }))
      fitted.push_back(t);
  constraints.parameters = kept;
  constraints.points.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const gp_Pnt p = curve.Value(kept[i]);
    constraints.points.row(static_cast<Eigen::Index>(i)) << p.X(), p.Y(), p.Z();
  }
  const bool smoothSeam = curve.IsClosed() && curve.DN(first, 1).Angle(curve.DN(last, 1)) < kCornerAngle;
  if (smoothSeam) constraints.seamContinuity = 2;

  std::vector<gp_Pnt> targets;
  for (double t : fitted) targets.push_back(curve.Value(t));

  // The sample parameters are corrected while the fit still improves noticeably.
  return fitCorrectingParameters(space, fitted, toMatrix(targets), constraints, FitError::Largest);
}

}  // namespace airshape::geometry
