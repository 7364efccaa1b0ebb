#include "airshape/geometry/profile_outline.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Bnd_Box2d.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

namespace {

/// Which side of the line a -> b (a side longer than `tolerance`) the point p lies on: +1
/// left, -1 right, 0 within `tolerance` of the line.
int sideOf(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& p, double tolerance) {
  const double distance = ((b.X() - a.X()) * (p.Y() - a.Y()) - (b.Y() - a.Y()) * (p.X() - a.X())) / a.Distance(b);
  return (distance > tolerance) - (distance < -tolerance);
}

/// Whether the sides ab and cd cross at a point inside both.
bool cross(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& c, const gp_Pnt2d& d, double tolerance) {
  return sideOf(a, b, c, tolerance) * sideOf(a, b, d, tolerance) < 0 &&
         sideOf(c, d, a, tolerance) * sideOf(c, d, b, tolerance) < 0;
}

/// The area the closed polygon encloses, positive where it runs anticlockwise (shoelace).
double signedArea(const std::vector<gp_Pnt2d>& corners) {
  double twice = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const gp_Pnt2d &a = corners[i], &b = corners[(i + 1) % corners.size()];
    twice += a.X() * b.Y() - b.X() * a.Y();
  }
  return twice / 2.0;
}

/// The diagonal of the corners' box: the polygon's size.
double diagonal(const std::vector<gp_Pnt2d>& corners) {
  Bnd_Box2d box;
  for (const gp_Pnt2d& corner : corners) box.Add(corner);
  return box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
}

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> polygonCrossing(const std::vector<gp_Pnt2d>& corners,
                                                                   double tolerance) {
  const std::size_t n = corners.size();
  if (n < 4) return std::nullopt;
  auto next = [n](std::size_t i) { return (i + 1) % n; };
  auto tooShort = [&](std::size_t i) { return corners[i].Distance(corners[next(i)]) <= tolerance; };
  for (std::size_t i = 0; i < n; ++i) {
    if (tooShort(i)) continue;
    // Neighbouring sides share a corner: they can only touch.
    for (std::size_t j = i + 2; j < n; ++j) {
      if (next(j) == i || tooShort(j)) continue;
      if (cross(corners[i], corners[next(i)], corners[j], corners[next(j)], tolerance)) return std::pair(i, j);
    }
  }
  return std::nullopt;
}

double crossingDepth(const std::vector<gp_Pnt2d>& corners, std::pair<std::size_t, std::size_t> sides) {
  const std::size_t n = corners.size();
  const gp_Pnt2d &a = corners[sides.first], &b = corners[(sides.first + 1) % n];
  const gp_Pnt2d &c = corners[sides.second], &d = corners[(sides.second + 1) % n];
  const auto distance = [](const gp_Pnt2d& from, const gp_Pnt2d& to, const gp_Pnt2d& p) {
    return std::abs((to.X() - from.X()) * (p.Y() - from.Y()) - (to.Y() - from.Y()) * (p.X() - from.X())) /
           from.Distance(to);
  };
  return std::min({distance(a, b, c), distance(a, b, d), distance(c, d, a), distance(c, d, b)});
}

std::optional<std::string> requireProfileOutline(const std::vector<gp_Pnt2d>& corners, double tolerance,
                                                 const std::vector<int>& placeInFile, const std::string& xpath) {
  if (corners.size() < 3) return std::nullopt;  // too few points: the caller's own error says so
  const double size = diagonal(corners);
  std::optional<std::string> warning;
  // A polygon that crosses itself may enclose no signed area (a bow tie): crossings first.
  if (const auto crossing = polygonCrossing(corners, tolerance)) {
    // Where sides cross by more than the tolerance, the deepest such crossing is the one to name.
    const auto deep = polygonCrossing(corners, std::max(tolerance, kToleratedCrossing * size));
    const auto named = deep ? *deep : *crossing;
    auto number = [&](std::size_t corner) {
      return (placeInFile.empty() ? static_cast<int>(corner) : placeInFile[corner]) + 1;
    };
    std::ostringstream what;
    what << std::setprecision(2) << "the points' outline crosses itself (its sides from point " << number(named.first)
         << " and from point " << number(named.second) << " cross by " << crossingDepth(corners, named) / size
         << " of the profile's size, " << (deep ? "more" : "less") << " than the tolerated " << kToleratedCrossing;
    if (deep) throw Error(ErrorCode::InvalidModel, what.str() + "): points out of order?", {}, xpath);
    warning = what.str() + "): lofted as given";
  }
  if (std::abs(signedArea(corners)) <= tolerance * size)
    throw Error(ErrorCode::InvalidModel, "the points enclose no area (they lie on a line)", {}, xpath);
  return warning;
}

}  // namespace airshape::geometry
