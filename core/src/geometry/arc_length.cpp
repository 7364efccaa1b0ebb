#include "airshape/geometry/arc_length.h"

#include <algorithm>
#include <cmath>

#include <gp_Vec.hxx>

#include "airshape/geometry/gauss_rule.h"

namespace airshape::geometry {

namespace {

constexpr int kGaussPoints = 16;
/// Two rules agreeing to this part of the length are trusted.
constexpr double kAgreement = 1e-14;
/// A speed varying by less than this factor over an interval needs no check of its rule.
constexpr double kSteadySpeed = 1.5;
/// Halvings of one interval at most (a speed that vanishes inside a span needs some).
constexpr int kMaxHalvings = 24;

/// The rule every interval is integrated with, computed once.
const GaussRule& gaussRule() {
  static const GaussRule rule(kGaussPoints);
  return rule;
}

}  // namespace

ArcLength::ArcLength(const Handle(Geom_BSplineCurve) & curve) : curve_(curve) {
  const double first = curve->FirstParameter(), last = curve->LastParameter();
  knots_.push_back(first);
  for (int i = 1; i <= curve->NbKnots(); ++i)
    if (curve->Knot(i) > first && curve->Knot(i) < last) knots_.push_back(curve->Knot(i));
  knots_.push_back(last);
  lengthToKnot_.push_back(0.0);
  for (std::size_t k = 0; k + 1 < knots_.size(); ++k)
    lengthToKnot_.push_back(lengthToKnot_.back() + integral(knots_[k], knots_[k + 1]));
}

double ArcLength::speed(double t) const {
  gp_Pnt point;
  gp_Vec tangent;
  curve_.D1(t, point, tangent);
  return tangent.Magnitude();
}

double ArcLength::integral(double from, double to) const {
  const GaussRule& rule = gaussRule();
  double slowest = 0.0, fastest = 0.0;
  auto gauss = [&](double a, double b) {
    const double middle = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0.0;
    slowest = HUGE_VAL;
    fastest = 0.0;
    for (int i = 0; i < kGaussPoints; ++i) {
      const double rate = speed(middle + half * rule.points(i + 1));
      slowest = std::min(slowest, rate);
      fastest = std::max(fastest, rate);
      sum += rule.weights(i + 1) * rate;
    }
    return sum * half;
  };
  // A speed that hardly changes over the interval (as on most knot spans of a profile) is
  // integrated by the rule to rounding: the speed's square is a polynomial of low degree whose
  // zeros lie far away then.
  const double whole = gauss(from, to);
  if (fastest <= kSteadySpeed * slowest) return whole;
  // Adaptive halving where the rule on an interval and on its halves disagree.
  struct Interval {
    double a, b, whole;
    int depth;
  };
  std::vector<Interval> pending = {{from, to, whole, 0}};
  double length = 0.0;
  while (!pending.empty()) {
    const Interval interval = pending.back();
    pending.pop_back();
    const double middle = 0.5 * (interval.a + interval.b);
    const double left = gauss(interval.a, middle), right = gauss(middle, interval.b);
    if (interval.depth >= kMaxHalvings ||
        std::abs(left + right - interval.whole) <= kAgreement * std::max(std::abs(left + right), 1e-300)) {
      length += left + right;
      continue;
    }
    pending.push_back({interval.a, middle, left, interval.depth + 1});
    pending.push_back({middle, interval.b, right, interval.depth + 1});
  }
  return length;
}

std::size_t ArcLength::spanOf(double t) const {
  const auto after = std::upper_bound(knots_.begin(), knots_.end(), t);
  const auto index = static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - knots_.begin() - 1, 0));
  return std::min(index, knots_.size() - 2);
}

double ArcLength::lengthAt(double t) const {
  t = std::clamp(t, knots_.front(), knots_.back());
  const std::size_t span = spanOf(t);
  return lengthToKnot_[span] + integral(knots_[span], t);
}

double ArcLength::parameterAt(double length) const {
  if (length <= 0.0) return knots_.front();
  if (length >= total()) return knots_.back();
  const auto after = std::upper_bound(lengthToKnot_.begin(), lengthToKnot_.end(), length);
  const auto span = static_cast<std::size_t>(after - lengthToKnot_.begin() - 1);
  // Newton's method on the length within the span, kept inside a shrinking bracket.
  double low = knots_[span], high = knots_[span + 1];
  const double within = length - lengthToKnot_[span], spanLength = lengthToKnot_[span + 1] - lengthToKnot_[span];
  double t = low + (high - low) * within / spanLength;
  constexpr int kMaxSteps = 60;
  for (int step = 0; step < kMaxSteps; ++step) {
    const double excess = integral(knots_[span], t) - within;
    if (std::abs(excess) <= kAgreement * total()) break;
    (excess > 0.0 ? high : low) = t;
    const double rate = speed(t);
    double next = rate > 0.0 ? t - excess / rate : 0.5 * (low + high);
    if (!(next > low && next < high)) next = 0.5 * (low + high);
    if (next == t) break;
    t = next;
  }
  return t;
}

}  // namespace airshape::geometry
