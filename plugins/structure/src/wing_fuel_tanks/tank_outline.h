#pragma once

#include <functional>
#include <vector>

#include <gp_Pnt.hxx>
#include <gp_XY.hxx>

namespace airshape::structure {

/// A region of a component segment seen from above (along the wing's z axis, in the wing
/// frame; z only serves to find a point's eta): the polygon a list of borders encloses, each
/// border followed from where it meets the previous one to where it meets the next.
class TankOutline {
 public:
  /// One border's line, carried beyond the component segment at both ends, with the part
  /// that is the element itself (positions along the line: piece index plus share); for a
  /// spar, the eta of its first and last position, so that an open list can be closed.
  struct Border {
    std::vector<gp_Pnt> line;
    double elementFrom = 0.0, elementTo = 1.0;
    bool spar = false;
    double firstEta = 0.0, lastEta = 1.0;
  };

  /// The order in which the borders go around a region: as listed when each meets the next
  /// (the last and the first may be spars that the component segment's end joins); else, for
  /// a list written in another order, the first order that closes (the first border kept
  /// first; lists up to eight borders long), preferring one whose every border meets the next;
  /// empty when there is none.
  static std::vector<std::size_t> orderAround(const std::vector<Border>& borders);

  /// The borders in the order they go around the region. Two spars meet only where both are; a rib's line meets
  /// whatever it crosses. Throws Error (no CPACS path: the caller knows it) when two consecutive borders do not meet,
  /// unless they are the last and the first border and both are spars: then the list is closed along the component
  /// segment's end (eta 0 or 1) nearer to the corners' mean eta.
  TankOutline(const std::vector<Border>& borders, const std::function<double(const gp_Pnt&)>& etaOf);

  /// Whether a point lies inside the outline seen from above.
  bool contains(const gp_Pnt& point) const;

 private:
  std::vector<gp_XY> polygon_;
};

}  // namespace airshape::structure
