#pragma once

#include <optional>
#include <string>

#include <gp_Pnt.hxx>

#include "wing_geometry.h"
#include "wing_shape.h"

namespace airshape::wing {

/// Where a point lies on a wing: segment, (eta, xsi) on the nearer skin, and whether it is
/// within 3 cm of the upper skin.
struct SegmentLocation {
  std::size_t segment;
  double eta, xsi;
  bool onTop;
};

/// Finds the segment that holds the point (inside or within 3 cm of its solid, or within
/// 3 cm of its chord surface; of two neighbours the nearer wins) and maps the point back to
/// eta and xsi by projecting it onto the segment's skins. Nothing found: nullopt.
std::optional<SegmentLocation> locateOnWing(const WingGeometry& geometry, const WingShape& shape, const gp_Pnt& point);

}  // namespace airshape::wing
