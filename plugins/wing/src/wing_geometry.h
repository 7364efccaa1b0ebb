#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gp_Pnt.hxx>

#include "airshape/model/placement.h"
#include "guided_wing_skin.h"
#include "wing_profile.h"

namespace airshape {
class Configuration;
}

namespace airshape::wing {

/// One end of a segment: its airfoil and the full transformation C · Pos · Sec · Elem that
/// takes the airfoil to global coordinates.
struct SegmentEnd {
  std::string elementUid;
  std::shared_ptr<const WingProfile> profile;
  model::Transform transform;

  gp_Pnt upper(double xsi) const;
  gp_Pnt lower(double xsi) const;
  gp_Pnt leadingEdge() const;
  gp_Pnt trailingEdge() const;
};

struct WingSegment {
  std::string uid;
  std::string xpath;  ///< where the segment is defined, for errors
  SegmentEnd inner, outer;
};

/// The geometry of one wing that the point queries need: its segments in chain order,
/// each with its two placed airfoils. The skins are ruled between them, or shaped by guide
/// curves where the wing has them (docs/wing.md).
class WingGeometry {
 public:
  /// Builds (or takes from the configuration's cache) the geometry of a wing. Throws Error
  /// naming the CPACS path of what is missing or inconsistent.
  static std::shared_ptr<const WingGeometry> of(const Configuration& configuration, const schema::WingType& wing);

  /// Where the wing is defined, for errors.
  const std::string& xpath() const { return wing_->xpath; }
  const std::vector<WingSegment>& segments() const { return segments_; }
  /// The segments' uIDs in chain order, for addressing them by index or uID.
  const std::vector<std::string>& segmentUids() const { return segmentUids_; }

  /// The skin shaped by guide curves, or null when the wing has none (ruled skins). Built
  /// on first use, so that queries that need no skin (MAC, areas of the chord surface) work
  /// even when the guide curves are broken.
  const GuidedWingSkin* guidedSkin() const;

  gp_Pnt upperPoint(std::size_t segment, double eta, double xsi) const;
  gp_Pnt lowerPoint(std::size_t segment, double eta, double xsi) const;
  gp_Pnt chordPoint(std::size_t segment, double eta, double xsi) const;

 private:
  std::vector<WingSegment> segments_;
  std::vector<std::string> segmentUids_;
  const Configuration* configuration_ = nullptr;
  const schema::WingType* wing_ = nullptr;
  mutable std::mutex guidedSkinMutex_;
  mutable std::shared_ptr<const GuidedWingSkin> guidedSkin_;
  mutable bool guidedSkinBuilt_ = false;
};

}  // namespace airshape::wing
