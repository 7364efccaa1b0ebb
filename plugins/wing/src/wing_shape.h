#pragma once

#include <map>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

#include "airshape/named_shape.h"
#include "wing_geometry.h"

namespace airshape {
class Configuration;
}

namespace airshape::wing {

/// The faces of one wing segment: ruled upper and lower skins (and a trailing-edge strip
/// for blunt airfoils) between its two placed airfoils, closed by planar caps. With guide
/// curves the skin is split at the leading-edge guide (one face in `upper`, `lower` empty,
/// when no guide runs along the leading edge).
struct SegmentShape {
  TopoDS_Face upper, lower, trailingEdge, innerCap, outerCap;
  TopoDS_Shape solid;          ///< none for a guided segment: WingShape::segmentSolid sews it
  bool sewnOnRequest = false;  ///< a guided segment's faces
};

/// The B-rep of a wing, segment by segment; measures are exact integrals over it.
class WingShape {
 public:
  static std::shared_ptr<const WingShape> of(const Configuration& configuration, const schema::WingType& wing);

  const std::vector<SegmentShape>& segments() const { return segments_; }
  /// The solid of one segment. A guided segment's faces are sewn into it on the first
  /// request only: exporting or measuring the whole wing never needs it, and sewing was
  /// two thirds of building a guided wing.
  const TopoDS_Shape& segmentSolid(std::size_t segment) const;

  double segmentVolume(std::size_t segment) const;
  /// Upper and lower skin of a segment.
  double segmentSurfaceArea(std::size_t segment) const;
  double volume() const;
  /// Every face of the wing solid: skins, trailing-edge strips, root and tip caps.
  double surfaceArea() const;

  /// The whole wing as one solid: every segment's skins and strips, the root and tip caps,
  /// named "<segment uID>/upper", "/lower", "/trailingEdge" ("/skin" where a guided skin
  /// has no leading-edge guide to split it), "<wing uID>/root" and "/tip".
  NamedShape solid() const;
  /// The solid of the segments first..last (chain order) alone: their skins and strips closed
  /// by the caps at their ends, named as in solid(); caps inside the wing are named
  /// "<segment uID>/inner" and "/outer". A wing segment's or component segment's shape.
  NamedShape solidOf(std::size_t first, std::size_t last) const;
  /// solidOf, made once per first..last and kept: what structure lies in.
  const NamedShape& closedSolidOf(std::size_t first, std::size_t last) const;
  /// A component segment's shape over the segments first..last: solidOf without the blunt
  /// trailing-edge strips, the skins and end caps as one open shell held by a solid.
  NamedShape componentSegmentShape(std::size_t first, std::size_t last) const;

 private:
  std::string wingUid_, wingPath_;
  std::vector<WingSegment> segmentDefinitions_;  ///< per segment: its uID, CPACS path and airfoils
  std::vector<SegmentShape> segments_;
  mutable std::mutex sewingSegments_;             ///< guards sewnSolids_
  mutable std::vector<TopoDS_Shape> sewnSolids_;  ///< per segment, once sewn on request
  mutable std::mutex keepingSolids_;              ///< guards closedSolids_
  mutable std::map<std::pair<std::size_t, std::size_t>, NamedShape> closedSolids_;  ///< by first..last
};

}  // namespace airshape::wing
