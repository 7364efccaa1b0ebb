#include "airshape/geometry/profile_outline.h"

#include <cmath>

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

void requireProfileOutline(const std::vector<gp_Pnt2d>& corners, double tolerance, const std::string& xpath,
                           const std::vector<int>& placeInFile) {
  if (corners.size() < 3) return;  // too few points: the caller's own error says so
  const auto crossing = polygonCrossing(corners, tolerance);
  // A polygon that crosses itself may enclose no signed area (a bow tie): crossings first.
  if (crossing) {
    auto number = [&](std::size_t corner) {
      return std::to_string((placeInFile.empty() ? static_cast<int>(corner) : placeInFile[corner]) + 1);
    };
    throw Error(ErrorCode::InvalidModel,
                "the points' outline crosses itself (its sides from point " + number(crossing->first) +
                    " and from point " + number(crossing->second) + " cross): points out of order?",
                {}, xpath);
  }
  if (std::abs(signedArea(corners)) <= tolerance * diagonal(corners))
    throw Error(ErrorCode::InvalidModel, "the points enclose no area (they lie on a line)", {}, xpath);
}

}  // namespace airshape::geometry
