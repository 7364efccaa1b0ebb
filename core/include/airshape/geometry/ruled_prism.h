#pragma once

#include <optional>
#include <vector>

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape::geometry {

/// The solid that lines through the corners of a closed polygon sweep, each line along its own
/// direction and as far as `reach` either way of its corner: a cell's prism. Each side is the
/// bilinear patch between two consecutive lines. Which side of it a point lies on is answered in
/// closed form, without OCCT's solid classification (three quarters of a large cell's time).
class RuledPrism {
 public:
  RuledPrism(const std::vector<gp_Pnt>& corners, const std::vector<gp_Vec>& directions, double reach);

  /// Whether the point lies inside, by the parity of the sides a ray from it crosses (the ray
  /// runs across the lines, so it leaves through the sides, not the ends). Nothing where the
  /// ray passes within rounding of a line through a corner or touches a side: the caller then
  /// asks a general classification.
  std::optional<bool> contains(const gp_Pnt& point) const;

 private:
  /// A side as a + t b + u c + t u d, t along the polygon's side, u along the lines (both 0 to 1).
  struct Side {
    gp_Vec a, b, c, d;
  };
  /// How often the ray from `point` along `ray_` crosses the side; nothing where it is unclear.
  std::optional<int> crossings(const Side& side, const gp_Pnt& point) const;

  std::vector<Side> sides_;
  double tiny_;                     // a distance within rounding of the prism's size
  gp_Vec ray_, across1_, across2_;  // the ray's direction and two directions square to it and each other
};

}  // namespace airshape::geometry
