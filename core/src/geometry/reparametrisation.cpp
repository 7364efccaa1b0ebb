#include "airshape/geometry/reparametrisation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <GeomAdaptor_Curve.hxx>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_approximation.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/parallel_for.h"

namespace airshape::geometry {

namespace {

constexpr int kMaxPoles = 1500;

/// σ: a scalar B-spline from target parameters to a curve's own parameters. For a closed
/// curve of the given period it is σ(s) = values[0] + period·s + δ(s) with δ periodic, so
/// that f∘σ is as smooth across the seam as f is.
class ParameterMap {
 public:
  ParameterMap(const std::vector<double>& targets, const std::vector<double>& values, int curveIndex, double period)
      : start_(values.front()), period_(period) {
    for (std::size_t i = 1; i < values.size(); ++i)
      if (!(values[i] > values[i - 1]))
        throw Error(ErrorCode::InvalidArgument, "curve " + std::to_string(curveIndex + 1) +
                                                    ": its crossings are not in increasing order, so no "
                                                    "reparametrisation maps onto them");
    std::vector<gp_Pnt> points;
    for (std::size_t i = 0; i < values.size(); ++i) points.emplace_back(values[i] - linear(targets[i]), 0.0, 0.0);
    const bool closed = period_ > 0.0;
    use(interpolateCurve(points, targets, 3, closed));
    if (!isIncreasing()) use(interpolateCurve(points, targets, 1, closed));  // piecewise linear is monotone
    if (!isIncreasing())
      throw Error(ErrorCode::InvalidArgument,
                  "curve " + std::to_string(curveIndex + 1) + ": the reparametrisation is not strictly increasing");
  }

  double operator()(double s) const { return linear(s) + evaluator_.Value(s).X(); }

  /// The target parameter that maps onto `value` (bisection; σ is increasing).
  double inverse(double value) const {
    double low = 0.0, high = 1.0;
    for (int i = 0; i < 80; ++i) {
      const double middle = 0.5 * (low + high);
      ((*this)(middle) < value ? low : high) = middle;
    }
    return 0.5 * (low + high);
  }

 private:
  bool isIncreasing() const {
    constexpr int kChecks = 400;
    double previous = (*this)(0.0);
    for (int i = 1; i <= kChecks; ++i) {
      const double s = static_cast<double>(i) / kChecks;
      const double value = (*this)(s);
      if (!(value > previous)) return false;
      previous = value;
    }
    return true;
  }

  double linear(double s) const { return period_ > 0.0 ? start_ + period_ * s : 0.0; }

  void use(const Handle(Geom_BSplineCurve) & map) {
    map_ = map;
    evaluator_.Load(map_);
  }

  Handle(Geom_BSplineCurve) map_;
  GeomAdaptor_Curve evaluator_;  ///< evaluates through OCCT's span cache: σ is asked span by span
  double start_;
  double period_;
};

/// One curve's crossings, unwrapped for closed curves so that they ascend from the first.
std::vector<double> unwrapped(const Geom_BSplineCurve& curve, std::vector<double> crossings, bool closed) {
  if (!closed) return crossings;
  const double period = curve.LastParameter() - curve.FirstParameter();
  for (std::size_t i = 1; i < crossings.size(); ++i)
    while (crossings[i] <= crossings[i - 1]) crossings[i] += period;
  return crossings;
}

/// The common targets: the mean over the family of each crossing's relative position.
std::vector<double> commonTargets(const CurveFamily& family, const std::vector<std::vector<double>>& crossings) {
  const std::size_t count = crossings.front().size();
  std::vector<double> targets(count, 0.0);
  for (std::size_t c = 0; c < family.curves.size(); ++c) {
    const auto& x = crossings[c];
    const double span =
        family.closed ? family.curves[c]->LastParameter() - family.curves[c]->FirstParameter() : x.back() - x.front();
    for (std::size_t i = 0; i < count; ++i)
      targets[i] += (x[i] - x.front()) / span / static_cast<double>(family.curves.size());
  }
  if (!family.closed) {
    targets.front() = 0.0;
    targets.back() = 1.0;
  }
  return targets;
}

double valueAt(const Geom_BSplineCurve& curve, double t, bool closed) {
  if (closed) {
    const double first = curve.FirstParameter(), period = curve.LastParameter() - first;
    t = first + std::fmod(std::fmod(t - first, period) + period, period);
  }
  return t;
}

/// Parameters of corners (knots of multiplicity >= degree) inside the used part of a curve.
std::vector<double> cornersOf(const Geom_BSplineCurve& curve, double from, double to) {
  std::vector<double> corners;
  for (int i = 2; i < curve.NbKnots(); ++i)
    if (curve.Multiplicity(i) >= curve.Degree() && curve.Knot(i) > from + 1e-9 && curve.Knot(i) < to - 1e-9)
      corners.push_back(curve.Knot(i));
  return corners;
}

struct Prepared {
  std::vector<ParameterMap> maps;
  std::vector<std::vector<double>> crossings;
  std::vector<double> targets;
  std::vector<double> cornerTargets;
  std::vector<double> featureKnots;  ///< knots added where curves needed them
};

/// Adds a knot of at least the given multiplicity (an existing knot within 1e-9 is raised).
void addKnot(KnotVector& space, double knot, int multiplicity) {
  auto position = std::lower_bound(space.knots.begin(), space.knots.end(), knot - 1e-9);
  const auto index = static_cast<std::size_t>(position - space.knots.begin());
  if (position != space.knots.end() && std::abs(*position - knot) < 1e-9) {
    space.multiplicities[index] = std::max(space.multiplicities[index], multiplicity);
  } else {
    space.knots.insert(position, knot);
    space.multiplicities.insert(space.multiplicities.begin() + static_cast<long>(index), multiplicity);
  }
}

/// Uniform knots for `poles` control points, plus the corners (triple knots) and features.
KnotVector spaceFor(int poles, const Prepared& prepared, bool closed) {
  KnotVector space = closed ? periodicUniformKnots(0.0, 1.0, poles, 3) : uniformKnots(0.0, 1.0, poles, 3);
  for (double feature : prepared.featureKnots)
    if (feature > space.first() + 1e-9 && feature < space.last() - 1e-9) addKnot(space, feature, 1);
  for (double corner : prepared.cornerTargets) addKnot(space, corner, 3);
  return space;
}

/// One curve approximated in a space: the curve, its largest sampled deviation from f∘σ,
/// and the parameters where it deviates more than the tolerance.
struct Approximation {
  Handle(Geom_BSplineCurve) curve;
  double deviation = 0.0;
  std::vector<double> misses;
};

/// Approximates f∘σ for one curve in `space`.
Approximation approximate(const Handle(Geom_BSplineCurve) & input, const ParameterMap& map,
                          const std::vector<double>& targets, const std::vector<double>& crossings,
                          const KnotVector& space, bool closed, double tolerance) {
  // Evaluated through OCCT's span cache (the samples go through the curves in order), several
  // times quicker than evaluating the curve afresh at each parameter.
  const Geom_BSplineCurve& curve = *input;
  const GeomAdaptor_Curve samples(input);
  // Samples in every knot span, so that no control point goes without data.
  constexpr int kSamplesPerSpan = 6;
  std::vector<double> parameters;
  for (std::size_t i = 0; i + 1 < space.knots.size(); ++i)
    for (int j = 0; j < kSamplesPerSpan; ++j)
      parameters.push_back(space.knots[i] + (space.knots[i + 1] - space.knots[i]) * j / kSamplesPerSpan);
  if (!closed) parameters.push_back(1.0);
  PoleMatrix points(static_cast<Eigen::Index>(parameters.size()), 3);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const gp_Pnt p = samples.Value(valueAt(curve, map(parameters[i]), closed));
    points.row(static_cast<Eigen::Index>(i)) << p.X(), p.Y(), p.Z();
  }
  InterpolationConstraints constraints;
  constraints.parameters = targets;
  constraints.points.resize(static_cast<Eigen::Index>(targets.size()), 3);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const gp_Pnt p = curve.Value(valueAt(curve, crossings[i], closed));
    constraints.points.row(static_cast<Eigen::Index>(i)) << p.X(), p.Y(), p.Z();
  }
  Approximation result;
  result.curve = makeCurve(space, approximatePoles(space, parameters, points, constraints));
  // Checked halfway between the fitted samples, where an approximation strays most.
  const GeomAdaptor_Curve fitted(result.curve);
  for (std::size_t i = 0; i + 1 < parameters.size(); ++i) {
    const double s = 0.5 * (parameters[i] + parameters[i + 1]);
    const double d = fitted.Value(s).Distance(samples.Value(valueAt(curve, map(s), closed)));
    result.deviation = std::max(result.deviation, d);
    if (d > tolerance) result.misses.push_back(s);
  }
  return result;
}

}  // namespace

ReparametrisedFamily reparametrise(const CurveFamily& family, double tolerance) {
  Prepared prepared;
  for (std::size_t c = 0; c < family.curves.size(); ++c)
    prepared.crossings.push_back(unwrapped(*family.curves[c], family.crossings[c], family.closed));
  prepared.targets = commonTargets(family, prepared.crossings);
  for (std::size_t c = 0; c < family.curves.size(); ++c) {
    std::vector<double> targets = prepared.targets, values = prepared.crossings[c];
    if (family.closed) {  // σ also covers the rest of the period, back to the first crossing
      targets.push_back(1.0);
      values.push_back(values.front() + family.curves[c]->LastParameter() - family.curves[c]->FirstParameter());
    }
    const double period = family.closed ? family.curves[c]->LastParameter() - family.curves[c]->FirstParameter() : 0.0;
    prepared.maps.emplace_back(targets, values, static_cast<int>(c), period);
    for (double corner : cornersOf(*family.curves[c], values.front(), values.back()))
      prepared.cornerTargets.push_back(prepared.maps.back().inverse(corner));
  }
  // Corners of different curves at one place (a section line) become one knot.
  std::sort(prepared.cornerTargets.begin(), prepared.cornerTargets.end());
  prepared.cornerTargets.erase(std::unique(prepared.cornerTargets.begin(), prepared.cornerTargets.end(),
                                           [](double a, double b) { return b - a < 1e-6; }),
                               prepared.cornerTargets.end());

  ReparametrisedFamily result;
  result.targets = prepared.targets;
  // Start with evenly spread knots, then halve every knot span where some curve still misses
  // f∘σ: knots go where the curves need them (clustered knots, tight bends), nowhere else.
  const int poles = static_cast<int>(prepared.targets.size()) + 12;
  for (int round = 0;; ++round) {
    const KnotVector space = spaceFor(poles, prepared, family.closed);
    result.curves.clear();
    result.maxDeviation = 0.0;
    std::vector<double> splits;
    // The curves are approximated independently, on every core.
    std::vector<Approximation> approximations(family.curves.size());
    parallelFor(family.curves.size(), [&](std::size_t c) {
      approximations[c] = approximate(family.curves[c], prepared.maps[c], prepared.targets, family.crossings[c], space,
                                      family.closed, tolerance);
    });
    for (const Approximation& a : approximations) {
      result.curves.push_back(a.curve);
      result.maxDeviation = std::max(result.maxDeviation, a.deviation);
      for (double s : a.misses) {
        const auto upper = std::upper_bound(space.knots.begin(), space.knots.end(), s);
        if (upper == space.knots.begin() || upper == space.knots.end()) continue;
        splits.push_back(0.5 * (*(upper - 1) + *upper));
      }
    }
    if (splits.empty() || space.poleCount() >= kMaxPoles) break;
    prepared.featureKnots.insert(prepared.featureKnots.end(), splits.begin(), splits.end());
    std::sort(prepared.featureKnots.begin(), prepared.featureKnots.end());
    prepared.featureKnots.erase(std::unique(prepared.featureKnots.begin(), prepared.featureKnots.end(),
                                            [](double x, double y) { return y - x < 1e-12; }),
                                prepared.featureKnots.end());
  }
  return result;
}

}  // namespace airshape::geometry
