#include "airshape/geometry/smallest_value.h"

#include <cmath>

namespace airshape::geometry {

namespace {

/// The golden section's share of an interval: a step into the larger part of it.
const double kGoldenShare = 0.5 * (3.0 - std::sqrt(5.0));

/// The step to the vertex of the parabola through (x, fx), (w, fw) and (v, fv), as its
/// numerator and denominator (denominator ≥ 0).
void parabolaStep(double x, double fx, double w, double fw, double v, double fv, double& numerator,
                  double& denominator) {
  const double r = (x - w) * (fx - fv);
  double q = (x - v) * (fx - fw);
  numerator = (x - v) * q - (x - w) * r;
  q = 2.0 * (q - r);
  if (q > 0.0) numerator = -numerator;
  denominator = std::abs(q);
}

}  // namespace

double argumentOfMinimum(const std::function<double(double)>& function, double low, double high, double tolerance) {
  // x: the best point so far, w: the second best, v: the one before w; step: the last step
  // taken, before: the one before it (a parabola's step must be less than half of it, or the
  // parabolas are not closing in).
  double x = low + kGoldenShare * (high - low), w = x, v = x;
  double fx = function(x), fw = fx, fv = fx;
  double step = 0.0, before = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double middle = 0.5 * (low + high);
    if (std::abs(x - middle) <= 2.0 * tolerance - 0.5 * (high - low)) break;
    bool parabola = false;
    if (std::abs(before) > tolerance) {
      double numerator = 0.0, denominator = 0.0;
      parabolaStep(x, fx, w, fw, v, fv, numerator, denominator);
      const double earlier = before;
      before = step;
      if (std::abs(numerator) < std::abs(0.5 * denominator * earlier) && numerator > denominator * (low - x) &&
          numerator < denominator * (high - x)) {
        step = numerator / denominator;
        const double u = x + step;
        // Not closer to an end than the tolerance: the end is known already.
        if (u - low < 2.0 * tolerance || high - u < 2.0 * tolerance) step = std::copysign(tolerance, middle - x);
        parabola = true;
      }
    }
    if (!parabola) {
      before = (x >= middle ? low : high) - x;
      step = kGoldenShare * before;
    }
    const double u = x + (std::abs(step) >= tolerance ? step : std::copysign(tolerance, step));
    const double fu = function(u);
    if (fu <= fx) {
      (u >= x ? low : high) = x;
      v = w, fv = fw;
      w = x, fw = fx;
      x = u, fx = fu;
    } else {
      (u < x ? low : high) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw;
        w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return x;
}

}  // namespace airshape::geometry
