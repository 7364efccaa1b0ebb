#include "tank_outline.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "airshape/error.h"

namespace airshape::structure {

namespace {

/// Where two lines cross seen from above: the position along each (piece index plus share).
struct Crossing {
  double first = 0.0, second = 0.0;
};

double cross(const gp_XY& a, const gp_XY& b) { return a.X() * b.Y() - a.Y() * b.X(); }
gp_XY seenFromAbove(const gp_Pnt& p) { return gp_XY(p.X(), p.Y()); }

/// Whether a position along a border lies on the element itself, not where it is carried.
bool onElement(const TankOutline::Border& border, double position) {
  constexpr double kTolerance = 1e-6;
  return position >= border.elementFrom - kTolerance && position <= border.elementTo + kTolerance;
}

/// Where two borders meet: two spars only where both are (carried beyond the component
/// segment, any two of them that are not parallel would meet), a rib wherever it crosses.
std::optional<Crossing> crossing(const TankOutline::Border& first, const TankOutline::Border& second) {
  const std::vector<gp_Pnt>&a = first.line, &b = second.line;
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      const gp_XY p = seenFromAbove(a[i]), r = seenFromAbove(a[i + 1]) - p;
      const gp_XY q = seenFromAbove(b[j]), s = seenFromAbove(b[j + 1]) - q;
      const double denominator = cross(r, s);
      if (std::abs(denominator) <= 1e-14 * r.Modulus() * s.Modulus()) continue;  // parallel pieces
      const double t = cross(q - p, s) / denominator, u = cross(q - p, r) / denominator;
      if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) continue;
      const Crossing found{i + t, j + u};
      if (first.spar && second.spar && !(onElement(first, found.first) && onElement(second, found.second))) continue;
      return found;
    }
  return std::nullopt;
}

gp_Pnt pointAt(const std::vector<gp_Pnt>& line, double position) {
  const std::size_t piece = std::min(static_cast<std::size_t>(std::max(position, 0.0)), line.size() - 2);
  const double share = position - static_cast<double>(piece);
  return gp_Pnt(line[piece].XYZ() * (1.0 - share) + line[piece + 1].XYZ() * share);
}

/// Appends a line's points from one position along it to (not including) another.
void follow(const std::vector<gp_Pnt>& line, double from, double to, std::vector<gp_XY>& polygon) {
  polygon.push_back(seenFromAbove(pointAt(line, from)));
  if (from < to) {
    for (auto k = static_cast<long>(std::floor(from)) + 1; k < to; ++k) polygon.push_back(seenFromAbove(line[k]));
  } else {
    for (auto k = static_cast<long>(std::ceil(from)) - 1; k > to; --k) polygon.push_back(seenFromAbove(line[k]));
  }
}

/// Whether the borders, in this order, each meet the next, and the last the first (or, where
/// `openAllowed`, are spars that the component segment's end can join).
bool goesAround(const std::vector<TankOutline::Border>& borders, const std::vector<std::size_t>& order,
                bool openAllowed) {
  for (std::size_t i = 0; i + 1 < order.size(); ++i)
    if (!crossing(borders[order[i]], borders[order[i + 1]])) return false;
  const TankOutline::Border &last = borders[order.back()], &first = borders[order.front()];
  return crossing(last, first) || (openAllowed && last.spar && first.spar);
}

std::string noMeeting(std::size_t first, std::size_t second) {
  return "border " + std::to_string(first + 1) + " and border " + std::to_string(second + 1) +
         " do not meet, seen from above";
}

}  // namespace

std::vector<std::size_t> TankOutline::orderAround(const std::vector<Border>& borders) {
  std::vector<std::size_t> listed(borders.size());
  for (std::size_t i = 0; i < listed.size(); ++i) listed[i] = i;
  if (listed.size() < 3 || goesAround(borders, listed, true)) return listed;
  constexpr std::size_t kLongestSearched = 8;  // 7! orders
  if (listed.size() > kLongestSearched) return {};
  for (const bool openAllowed : {false, true}) {
    std::vector<std::size_t> order = listed;
    do {
      if (goesAround(borders, order, openAllowed)) return order;
    } while (std::next_permutation(order.begin() + 1, order.end()));
  }
  return {};
}

TankOutline::TankOutline(const std::vector<Border>& borders, const std::function<double(const gp_Pnt&)>& etaOf) {
  const std::size_t n = borders.size();
  if (n < 3) throw Error(ErrorCode::InvalidModel, "a wing fuel tank needs at least three borders");
  std::vector<Crossing> corners;  // corners[i]: where border i meets border i + 1
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const auto corner = crossing(borders[i], borders[i + 1]);
    if (!corner) throw Error(ErrorCode::InvalidModel, noMeeting(i, i + 1));
    corners.push_back(*corner);
  }
  const auto closing = crossing(borders[n - 1], borders[0]);
  if (closing) {
    corners.push_back(*closing);
    for (std::size_t i = 0; i < n; ++i)
      follow(borders[i].line, corners[(i + n - 1) % n].second, corners[i].first, polygon_);
    return;
  }
  if (!borders[0].spar || !borders[n - 1].spar) throw Error(ErrorCode::InvalidModel, noMeeting(n - 1, 0));
  // Open: the end of the component segment nearer to the corners closes it, beyond which the
  // first and the last spar's lines are carried.
  double meanEta = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) meanEta += etaOf(pointAt(borders[i].line, corners[i].first));
  const bool closedInside = meanEta / static_cast<double>(corners.size()) < 0.5;
  auto endTowardsClosingSide = [&](const Border& border) {
    const bool firstIsInner = border.firstEta <= border.lastEta;
    return firstIsInner == closedInside ? 0.0 : static_cast<double>(border.line.size() - 1);
  };
  follow(borders[0].line, endTowardsClosingSide(borders[0]), corners[0].first, polygon_);
  for (std::size_t i = 1; i + 1 < n; ++i) follow(borders[i].line, corners[i - 1].second, corners[i].first, polygon_);
  follow(borders[n - 1].line, corners[n - 2].second, endTowardsClosingSide(borders[n - 1]), polygon_);
  polygon_.push_back(seenFromAbove(pointAt(borders[n - 1].line, endTowardsClosingSide(borders[n - 1]))));
}

bool TankOutline::contains(const gp_Pnt& point) const {
  // Even-odd rule: count the polygon's sides that a ray along +x from the point crosses.
  const gp_XY p = seenFromAbove(point);
  bool inside = false;
  for (std::size_t i = 0, j = polygon_.size() - 1; i < polygon_.size(); j = i++) {
    const gp_XY &a = polygon_[i], &b = polygon_[j];
    if ((a.Y() > p.Y()) == (b.Y() > p.Y())) continue;
    const double x = a.X() + (p.Y() - a.Y()) / (b.Y() - a.Y()) * (b.X() - a.X());
    if (p.X() < x) inside = !inside;
  }
  return inside;
}

}  // namespace airshape::structure
