#include "airshape/geometry/reparametrisation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_approximation.h"
#include "airshape/geometry/curve_interpolation.h"

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
    map_ = interpolateCurve(points, targets, 3, closed);
    if (!isIncreasing()) map_ = interpolateCurve(points, targets, 1, closed);  // piecewise linear is monotone
    if (!isIncreasing())
      throw Error(ErrorCode::InvalidArgument,
                  "curve " + std::to_string(curveIndex + 1) + ": the reparametrisation is not strictly increasing");
  }

  double operator()(double s) const { return linear(s) + map_->Value(s).X(); }

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

  Handle(Geom_BSplineCurve) map_;
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
};

KnotVector spaceFor(int poles, const std::vector<double>& corners, bool closed) {
  KnotVector space = closed ? periodicUniformKnots(0.0, 1.0, poles, 3) : uniformKnots(0.0, 1.0, poles, 3);
  for (double corner : corners) {
    auto position = std::lower_bound(space.knots.begin(), space.knots.end(), corner);
    const auto index = position - space.knots.begin();
    if (position != space.knots.end() && std::abs(*position - corner) < 1e-9) {
      space.multiplicities[static_cast<std::size_t>(index)] = 3;
    } else {
      space.knots.insert(position, corner);
      space.multiplicities.insert(space.multiplicities.begin() + index, 3);
    }
  }
  return space;
}

/// Approximates f∘σ for one curve in `space`; returns the curve and its sampled deviation.
std::pair<Handle(Geom_BSplineCurve), double> approximate(const Geom_BSplineCurve& curve, const ParameterMap& map,
                                                         const std::vector<double>& targets,
                                                         const std::vector<double>& crossings, const KnotVector& space,
                                                         bool closed) {
  // Samples in every knot span, so that no control point goes without data.
  constexpr int kSamplesPerSpan = 6;
  std::vector<double> parameters;
  for (std::size_t i = 0; i + 1 < space.knots.size(); ++i)
    for (int j = 0; j < kSamplesPerSpan; ++j)
      parameters.push_back(space.knots[i] + (space.knots[i + 1] - space.knots[i]) * j / kSamplesPerSpan);
  if (!closed) parameters.push_back(1.0);
  PoleMatrix points(static_cast<Eigen::Index>(parameters.size()), 3);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const gp_Pnt p = curve.Value(valueAt(curve, map(parameters[i]), closed));
    points.row(static_cast<Eigen::Index>(i)) << p.X(), p.Y(), p.Z();
  }
  InterpolationConstraints constraints;
  constraints.parameters = targets;
  constraints.points.resize(static_cast<Eigen::Index>(targets.size()), 3);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const gp_Pnt p = curve.Value(valueAt(curve, crossings[i], closed));
    constraints.points.row(static_cast<Eigen::Index>(i)) << p.X(), p.Y(), p.Z();
  }
  Handle(Geom_BSplineCurve) result = makeCurve(space, approximatePoles(space, parameters, points, constraints));
  double deviation = 0.0;
  const int checks = 2 * static_cast<int>(parameters.size());
  for (int i = 0; i < checks; ++i) {  // checked between the fitted samples too
    const double s = (i + 0.5) / checks;
    deviation = std::max(deviation, result->Value(s).Distance(curve.Value(valueAt(curve, map(s), closed))));
  }
  return {result, deviation};
}

}  // namespace

ReparametrisedFamily reparametrise(const CurveFamily& family, double tolerance) {
  Prepared prepared;
  for (std::size_t c = 0; c < family.curves.size(); ++c)
    prepared.crossings.push_back(unwrapped(*family.curves[c], family.crossings[c], family.closed));
  prepared.targets = commonTargets(family, prepared.crossings);
  int poles = static_cast<int>(prepared.targets.size()) + 4;  // grown below until accurate enough
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
  for (;;) {
    const KnotVector space = spaceFor(poles, prepared.cornerTargets, family.closed);
    result.curves.clear();
    result.maxDeviation = 0.0;
    for (std::size_t c = 0; c < family.curves.size(); ++c) {
      auto [curve, deviation] =
          approximate(*family.curves[c], prepared.maps[c], prepared.targets, family.crossings[c], space, family.closed);
      result.curves.push_back(curve);
      result.maxDeviation = std::max(result.maxDeviation, deviation);
    }
    if (result.maxDeviation <= tolerance || poles >= kMaxPoles) break;
    poles = std::min(kMaxPoles, poles * 3 / 2 + 1);
  }
  return result;
}

}  // namespace airshape::geometry
