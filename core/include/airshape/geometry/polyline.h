#pragma once

#include <optional>
#include <vector>

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape::geometry {

/// A line of straight pieces (a web's midplane line, a leading edge),
/// parametrised by the share of its length: 0 at its first point, 1 at its last.
class Polyline {
 public:
  explicit Polyline(std::vector<gp_Pnt> points);

  double length() const { return length_; }
  const std::vector<gp_Pnt>& points() const { return points_; }
  /// The point at a share of the length (shares beyond [0, 1] continue the end pieces).
  gp_Pnt at(double share) const;
  /// The direction of the piece at a share of the length (normalised).
  gp_Vec directionAt(double share) const;
  /// The share of the length where the line first crosses the plane through `origin` normal
  /// to `normal`, if it does.
  std::optional<double> crossing(const gp_Pnt& origin, const gp_Vec& normal) const;
  /// The share of the length of the line's point nearest to `point`.
  double nearestShare(const gp_Pnt& point) const;
  /// The line's corners strictly between two shares, in order from `from` to `to`.
  std::vector<gp_Pnt> cornersBetween(double from, double to) const;
  /// The line followed by another that starts where it ends.
  Polyline joined(const Polyline& next) const;

 private:
  std::size_t pieceAt(double share, double& along) const;

  std::vector<gp_Pnt> points_;
  std::vector<double> lengths_;  ///< cumulated, one per point
  double length_ = 0.0;
};

}  // namespace airshape::geometry
