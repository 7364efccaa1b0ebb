#include "naca_four_digit.h"

#include <cmath>

namespace airshape::wing {

NacaFourDigit::NacaFourDigit(double camber, double camberAt, double thickness, double trailingEdge)
    : camber_(camber),
      camberAt_(camberAt),
      thickness_(thickness),
      a4_(thickness > 0.0 ? trailingEdge / (10.0 * thickness) - 0.1036 : 0.0) {}

gp_Pnt NacaFourDigit::side(double x, double sign) const {
  const auto [height, slope] = camberLine(x);
  const double t = halfThickness(x), norm = std::sqrt(1.0 + slope * slope);
  return gp_Pnt(x - sign * t * slope / norm, 0.0, height + sign * t / norm);
}

double NacaFourDigit::chordwise(double xsi) {
  constexpr double e = 0.02;
  return (1.0 + e) * xsi * xsi / (xsi + e);
}

double NacaFourDigit::halfThickness(double x) const {
  return 5.0 * thickness_ *
         (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x + a4_ * x * x * x * x);
}

std::pair<double, double> NacaFourDigit::camberLine(double x) const {
  if (camber_ == 0.0 || camberAt_ == 0.0) return {0.0, 0.0};
  const double q = x < camberAt_ ? camberAt_ * camberAt_ : (1 - camberAt_) * (1 - camberAt_);
  const double height = x < camberAt_ ? 2 * camberAt_ * x - x * x : (1 - 2 * camberAt_) + 2 * camberAt_ * x - x * x;
  return {camber_ / q * height, 2 * camber_ / q * (camberAt_ - x)};
}

}  // namespace airshape::wing
