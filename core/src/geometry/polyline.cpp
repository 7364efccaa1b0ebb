#include "airshape/geometry/polyline.h"

#include <algorithm>
#include <cmath>

#include "airshape/error.h"

namespace airshape::geometry {

Polyline::Polyline(std::vector<gp_Pnt> points) : points_(std::move(points)) {
  if (points_.size() < 2) throw Error(ErrorCode::InvalidModel, "a line needs two points");
  lengths_.push_back(0.0);
  for (std::size_t i = 1; i < points_.size(); ++i)
    lengths_.push_back(lengths_.back() + points_[i - 1].Distance(points_[i]));
  length_ = lengths_.back();
  if (length_ <= 0.0) throw Error(ErrorCode::InvalidModel, "a line has no length");
}

std::size_t Polyline::pieceAt(double share, double& along) const {
  const double distance = share * length_;
  std::size_t piece = 0;
  while (piece + 2 < points_.size() && distance > lengths_[piece + 1]) ++piece;
  const double pieceLength = lengths_[piece + 1] - lengths_[piece];
  along = pieceLength > 0.0 ? (distance - lengths_[piece]) / pieceLength : 0.0;
  return piece;
}

gp_Pnt Polyline::at(double share) const {
  double along = 0.0;
  const std::size_t piece = pieceAt(share, along);
  return points_[piece].Translated(along * gp_Vec(points_[piece], points_[piece + 1]));
}

gp_Vec Polyline::directionAt(double share) const {
  double along = 0.0;
  const std::size_t piece = pieceAt(share, along);
  return gp_Vec(points_[piece], points_[piece + 1]).Normalized();
}

std::optional<double> Polyline::crossing(const gp_Pnt& origin, const gp_Vec& normal) const {
  // An end lying on the plane up to rounding counts as on it (a line built to end on a plate).
  const double onPlane = 1e-9 * std::max(1.0, length_) * normal.Magnitude();
  auto side = [&](const gp_Pnt& p) {
    const double distance = gp_Vec(origin, p).Dot(normal);
    return std::abs(distance) <= onPlane ? 0.0 : distance;
  };
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const double a = side(points_[i]), b = side(points_[i + 1]);
    if ((a > 0.0 && b > 0.0) || (a < 0.0 && b < 0.0) || a == b) continue;
    const double t = a / (a - b);
    return (lengths_[i] + t * (lengths_[i + 1] - lengths_[i])) / length_;
  }
  return std::nullopt;
}

double Polyline::nearestShare(const gp_Pnt& point) const {
  double best = 0.0, bestDistance = point.SquareDistance(points_.front());
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const gp_Vec piece(points_[i], points_[i + 1]);
    const double squared = piece.SquareMagnitude();
    const double t = squared > 0.0 ? std::clamp(gp_Vec(points_[i], point).Dot(piece) / squared, 0.0, 1.0) : 0.0;
    const double distance = point.SquareDistance(points_[i].Translated(t * piece));
    if (distance < bestDistance)
      bestDistance = distance, best = (lengths_[i] + t * (lengths_[i + 1] - lengths_[i])) / length_;
  }
  return best;
}

std::vector<gp_Pnt> Polyline::cornersBetween(double from, double to) const {
  const double low = std::min(from, to) * length_, high = std::max(from, to) * length_;
  const double margin = 1e-9 * length_;
  std::vector<gp_Pnt> corners;
  for (std::size_t i = 1; i + 1 < points_.size(); ++i)
    if (lengths_[i] > low + margin && lengths_[i] < high - margin) corners.push_back(points_[i]);
  if (from > to) std::reverse(corners.begin(), corners.end());
  return corners;
}

Polyline Polyline::joined(const Polyline& next) const {
  std::vector<gp_Pnt> points = points_;
  points.insert(points.end(), next.points_.begin() + 1, next.points_.end());
  return Polyline(points);
}

}  // namespace airshape::geometry
