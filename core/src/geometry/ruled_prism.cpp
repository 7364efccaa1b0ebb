#include "airshape/geometry/ruled_prism.h"

#include <array>
#include <cmath>

namespace airshape::geometry {

namespace {

/// Whether a parameter lies within rounding of a bound of [0, 1].
bool nearBound(double parameter) { return std::abs(parameter) < 1e-9 || std::abs(parameter - 1.0) < 1e-9; }

}  // namespace

RuledPrism::RuledPrism(const std::vector<gp_Pnt>& corners, const std::vector<gp_Vec>& directions, double reach)
    : tiny_(1e-12 * reach) {
  const std::size_t n = corners.size();
  gp_Vec mean(0, 0, 0);
  for (const gp_Vec& direction : directions) mean += direction.Normalized();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    const gp_Vec from(corners[k].XYZ() - reach * directions[k].XYZ());
    const gp_Vec to(corners[next].XYZ() - reach * directions[next].XYZ());
    const gp_Vec fromLine = 2.0 * reach * directions[k], toLine = 2.0 * reach * directions[next];
    sides_.push_back({from, to - from, fromLine, toLine - fromLine});
  }
  // The ray: square to the lines' mean direction, turned off the polygon's first side by an
  // odd angle, so that it runs along no side of a cell's outline.
  gp_Vec across = gp_Vec(corners[1].XYZ() - corners[0].XYZ()).Crossed(mean);
  if (across.Magnitude() <= 1e-12 * mean.Magnitude() * corners[1].Distance(corners[0]))
    across = mean.Crossed(std::abs(mean.X()) < 0.9 * mean.Magnitude() ? gp_Vec(1, 0, 0) : gp_Vec(0, 1, 0));
  across.Normalize();
  ray_ = (across + 0.3183098861837907 * mean.Normalized().Crossed(across)).Normalized();
  across1_ = ray_.Crossed(mean).Normalized();
  across2_ = ray_.Crossed(across1_);
}

std::optional<int> RuledPrism::crossings(const Side& side, const gp_Pnt& point) const {
  // The ray meets the side where a + t b + u c + t u d − point has no part across the ray: two
  // equations A + t B + u C + t u D = 0; u from the first put into the second leaves a quadratic
  // in t.
  const gp_Vec offset = side.a - gp_Vec(point.XYZ());
  const double a1 = offset.Dot(across1_), b1 = side.b.Dot(across1_), c1 = side.c.Dot(across1_),
               d1 = side.d.Dot(across1_);
  const double a2 = offset.Dot(across2_), b2 = side.b.Dot(across2_), c2 = side.c.Dot(across2_),
               d2 = side.d.Dot(across2_);
  const double q2 = b2 * d1 - b1 * d2, q1 = a2 * d1 + b2 * c1 - a1 * d2 - b1 * c2, q0 = a2 * c1 - a1 * c2;
  std::array<double, 2> roots{};
  std::size_t rootCount = 0;
  const double scale = std::abs(q2) + std::abs(q1) + std::abs(q0);
  if (scale == 0.0) return std::nullopt;  // the ray lies in the side
  if (std::abs(q2) <= 1e-12 * scale) {
    if (std::abs(q1) <= 1e-12 * scale) return 0;  // parallel to it
    roots[rootCount++] = -q0 / q1;
  } else {
    const double discriminant = q1 * q1 - 4.0 * q2 * q0;
    if (std::abs(discriminant) <= 1e-12 * q1 * q1) return std::nullopt;  // touching
    if (discriminant < 0.0) return 0;
    const double root = std::sqrt(discriminant);
    // The two roots without cancellation.
    const double q = -0.5 * (q1 + std::copysign(root, q1));
    roots[rootCount++] = q / q2;
    if (q != 0.0) roots[rootCount++] = q0 / q;
  }
  int count = 0;
  for (std::size_t k = 0; k < rootCount; ++k) {
    const double t = roots[k];
    if (t < -1e-9 || t > 1.0 + 1e-9) continue;
    if (nearBound(t)) return std::nullopt;  // through a corner's line
    const double first = c1 + t * d1, second = c2 + t * d2;
    const bool useFirst = std::abs(first) >= std::abs(second);
    const double denominator = useFirst ? first : second;
    if (std::abs(denominator) <= 1e-12 * (std::abs(c1) + std::abs(c2) + std::abs(d1) + std::abs(d2)))
      return std::nullopt;
    const double u = -(useFirst ? a1 + t * b1 : a2 + t * b2) / denominator;
    if (u < -1e-9 || u > 1.0 + 1e-9) continue;
    if (nearBound(u)) return std::nullopt;  // at an end of the lines
    const gp_Vec hit = side.a + t * side.b + u * side.c + t * u * side.d;
    const double ahead = (hit - gp_Vec(point.XYZ())).Dot(ray_);
    if (std::abs(ahead) <= tiny_) return std::nullopt;  // the point on the side
    if (ahead > 0.0) ++count;
  }
  return count;
}

std::optional<bool> RuledPrism::contains(const gp_Pnt& point) const {
  int total = 0;
  for (const Side& side : sides_) {
    const std::optional<int> count = crossings(side, point);
    if (!count) return std::nullopt;
    total += *count;
  }
  return total % 2 == 1;
}

}  // namespace airshape::geometry
