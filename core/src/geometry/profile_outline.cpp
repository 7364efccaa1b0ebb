#include "airshape/geometry/profile_outline.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Bnd_Box2d.hxx>
#include <gp_Vec2d.hxx>

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

namespace {

/// Calls `found` with each pair of crossing sides until it returns false.
template <typename Found>
void forEachCrossing(const std::vector<gp_Pnt2d>& corners, double tolerance, Found found) {
  const std::size_t n = corners.size();
  if (n < 4) return;
  auto next = [n](std::size_t i) { return (i + 1) % n; };
  auto tooShort = [&](std::size_t i) { return corners[i].Distance(corners[next(i)]) <= tolerance; };
  for (std::size_t i = 0; i < n; ++i) {
    if (tooShort(i)) continue;
    // Neighbouring sides share a corner: they can only touch.
    for (std::size_t j = i + 2; j < n; ++j) {
      if (next(j) == i || tooShort(j)) continue;
      if (cross(corners[i], corners[next(i)], corners[j], corners[next(j)], tolerance) && !found(std::pair(i, j)))
        return;
    }
  }
}

/// How many sides apart two sides of a closed polygon of `n` sides lie, the shorter way round.
std::size_t sidesApart(std::pair<std::size_t, std::size_t> sides, std::size_t n) {
  const std::size_t apart = sides.second - sides.first;
  return std::min(apart, n - apart);
}

/// Whether two crossing sides make a zig-zag: a few sides apart on an outline of many.
bool isZigZag(std::pair<std::size_t, std::size_t> sides, std::size_t n) {
  return n > 3 * kZigZagReach && sidesApart(sides, n) <= kZigZagReach;
}

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> polygonCrossing(const std::vector<gp_Pnt2d>& corners,
                                                                   double tolerance) {
  std::optional<std::pair<std::size_t, std::size_t>> first;
  forEachCrossing(corners, tolerance, [&](std::pair<std::size_t, std::size_t> sides) {
    first = sides;
    return false;
  });
  return first;
}

std::vector<std::pair<std::size_t, std::size_t>> polygonCrossings(const std::vector<gp_Pnt2d>& corners,
                                                                  double tolerance) {
  std::vector<std::pair<std::size_t, std::size_t>> all;
  forEachCrossing(corners, tolerance, [&](std::pair<std::size_t, std::size_t> sides) {
    all.push_back(sides);
    return true;
  });
  return all;
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

std::vector<ZigZag> zigZags(const std::vector<gp_Pnt2d>& corners, double tolerance) {
  const std::size_t n = corners.size();
  const double size = diagonal(corners);
  std::vector<ZigZag> found;
  for (const auto& [i, j] : polygonCrossings(corners, tolerance)) {
    const bool closingSide = j + 1 >= n;  // the side from the last corner back to the first
    if (closingSide || !isZigZag({i, j}, n) || (!found.empty() && i <= found.back().lastSide)) continue;
    const double depth = crossingDepth(corners, {i, j});
    if (depth > kToleratedZigZag * size) continue;
    const gp_Vec2d side(corners[i], corners[i + 1]), other(corners[j], corners[j + 1]);
    const double along = gp_Vec2d(corners[i], corners[j]).Crossed(other) / side.Crossed(other);
    found.push_back({i, j, along, depth});
  }
  return found;
}

std::vector<gp_Pnt> withoutZigZags(const std::vector<gp_Pnt>& points, const std::vector<ZigZag>& zigZags) {
  std::vector<gp_Pnt> kept;
  std::size_t next = 0;
  for (const ZigZag& zigZag : zigZags) {
    kept.insert(kept.end(), points.begin() + static_cast<long>(next),
                points.begin() + static_cast<long>(zigZag.firstSide + 1));
    const gp_XYZ& from = points[zigZag.firstSide].XYZ();
    kept.emplace_back(from + zigZag.along * (points[zigZag.firstSide + 1].XYZ() - from));
    next = zigZag.lastSide + 1;
  }
  kept.insert(kept.end(), points.begin() + static_cast<long>(next), points.end());
  return kept;
}

std::optional<std::string> requireProfileOutline(const std::vector<gp_Pnt2d>& corners, double tolerance,
                                                 const std::vector<int>& placeInFile, const std::string& xpath) {
  if (corners.size() < 3) return std::nullopt;  // too few points: the caller's own error says so
  const double size = diagonal(corners);
  std::optional<std::string> warning;
  // A polygon that crosses itself may enclose no signed area (a bow tie): crossings first. The
  // crossing to name is the first one deeper than it may be, else the deepest one.
  std::optional<std::pair<std::size_t, std::size_t>> named;
  double namedShare = -1, namedAllowed = 0;
  bool refused = false;
  for (const auto& sides : polygonCrossings(corners, tolerance)) {
    const double share = crossingDepth(corners, sides) / size;
    const double allowed = isZigZag(sides, corners.size()) ? kToleratedZigZag : kToleratedCrossing;
    if (share > allowed || (!refused && share > namedShare)) {
      named = sides, namedShare = share, namedAllowed = allowed;
      refused = share > allowed;
      if (refused) break;
    }
  }
  if (named) {
    auto number = [&](std::size_t corner) {
      return (placeInFile.empty() ? static_cast<int>(corner) : placeInFile[corner]) + 1;
    };
    std::ostringstream what;
    what << std::setprecision(2) << "the points' outline crosses itself (its sides from point " << number(named->first)
         << " and from point " << number(named->second) << " cross by " << namedShare << " of the profile's size, "
         << (refused ? "more" : "less") << " than the tolerated " << namedAllowed
         << (namedAllowed == kToleratedZigZag
                 ? " for a zig-zag of sides at most " + std::to_string(kZigZagReach) + " apart"
                 : std::string());
    if (refused) throw Error(ErrorCode::InvalidModel, what.str() + "): points out of order?", {}, xpath);
    warning = what.str() + "): lofted as given";
  }
  if (std::abs(signedArea(corners)) <= tolerance * size)
    throw Error(ErrorCode::InvalidModel, "the points enclose no area (they lie on a line)", {}, xpath);
  return warning;
}

}  // namespace airshape::geometry
