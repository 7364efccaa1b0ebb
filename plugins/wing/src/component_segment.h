#pragma once

#include <string>
#include <utility>
#include <vector>

#include "airshape/schema/generated/cpacs_model.h"
#include "wing_geometry.h"

namespace airshape::wing {

/// A component segment: the run of wing segments from one element to another, with eta
/// measured along the chord midpoints of its elements (3-D distances, normalised).
class ComponentSegment {
 public:
  /// Throws Error when no run of segments joins the two elements.
  ComponentSegment(const WingGeometry& wing, const schema::ComponentSegmentType& definition);

  struct SegmentPoint {
    std::size_t segment;  ///< index into the wing's segments
    double eta, xsi;
  };

  /// Component-segment (eta, xsi) to segment coordinates; an eta on a section break goes to
  /// the outer segment (with eta 0), except 1, which stays in the last.
  SegmentPoint toSegment(double eta, double xsi) const;
  /// Segment coordinates to component-segment eta (xsi is unchanged). Throws Error when
  /// the segment is not part of this component segment.
  double toComponentSegment(std::size_t segment, double eta) const;
  /// The wing segments it runs through (indices in chain order), inner to outer.
  const std::vector<std::size_t>& segments() const { return path_; }
  /// The first and the last of them in chain order: the wing's segments first..last are its.
  std::pair<std::size_t, std::size_t> segmentRange() const;

 private:
  std::vector<std::size_t> path_;    ///< wing segment indices, inner to outer
  std::vector<double> elementEtas_;  ///< one more than the path: 0 ... 1
  std::string uid_;
};

}  // namespace airshape::wing
