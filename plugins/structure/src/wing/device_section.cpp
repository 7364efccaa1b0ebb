#include "device_section.h"

#include <algorithm>
#include <limits>

#include <BRepBndLib.hxx>
#include <gp_Pln.hxx>

#include "airshape/geometry/plane_region.h"
#include "airshape/geometry/ruled_solid_section.h"

namespace airshape::structure {

DeviceSection::DeviceSection(const StructureFrame& frame, TopoDS_Shape cutter)
    : frame_(frame), cutter_(std::move(cutter)), tolerance_(geometry::kTraceTolerance * frame.reach()) {}

std::optional<std::vector<TopoDS_Face>> DeviceSection::faces(const geometry::CrossingLines& lines,
                                                             const geometry::CrossingEnd& from,
                                                             const geometry::CrossingEnd& to,
                                                             geometry::OpenEnds openEnds) const {
  const gp_Pln plane(lines.origin, lines.planeNormal());
  const std::optional<geometry::PlaneRegion> device = geometry::ruledSolidSection(cutter_, plane, tolerance_);
  if (!device || device->empty()) return std::nullopt;
  const std::optional<TopoDS_Face> section = wingSection(lines, from, to, openEnds);
  if (!section) return std::nullopt;
  const std::optional<geometry::PlaneRegion> wing = geometry::regionOf(plane, *section);
  if (!wing) return std::nullopt;
  std::optional<std::vector<TopoDS_Face>> faces = geometry::commonOf(plane, *wing, *device, tolerance_);
  if (!faces || faces->empty()) return std::nullopt;
  return faces;
}

std::optional<TopoDS_Face> DeviceSection::wingSection(const geometry::CrossingLines& lines, geometry::CrossingEnd from,
                                                      geometry::CrossingEnd to, geometry::OpenEnds openEnds) const {
  if (!wingSkins_) wingSkins_.emplace(frame_.componentSegmentSkin(true), frame_.componentSegmentSkin(false));
  if (!deviceBox_) {
    deviceBox_.emplace();
    BRepBndLib::Add(frame_.solid(), *deviceBox_, false);
  }
  double first = std::numeric_limits<double>::max(), last = -first;
  double x[2], y[2], z[2];
  deviceBox_->Get(x[0], y[0], z[0], x[1], y[1], z[1]);
  for (int corner = 0; corner < 8; ++corner) {
    const double t = lines.lineThrough(gp_Pnt(x[corner & 1], y[(corner >> 1) & 1], z[(corner >> 2) & 1]));
    first = std::min(first, t), last = std::max(last, t);
  }
  const double margin = 1e-3 * (last - first);
  const auto& [upperSkin, lowerSkin] = *wingSkins_;
  const auto upper = geometry::crossingSpan(upperSkin, lines, tolerance_),
             lower = geometry::crossingSpan(lowerSkin, lines, tolerance_);
  if (upper && lower) {
    if (from.kind == geometry::CrossingEnd::Kind::Open && first - margin > std::max(upper->first, lower->first))
      from = geometry::CrossingEnd::atLine(first - margin);
    if (to.kind == geometry::CrossingEnd::Kind::Open && last + margin < std::min(upper->second, lower->second))
      to = geometry::CrossingEnd::atLine(last + margin);
  }
  return geometry::sectionBetweenSkins(upperSkin, lowerSkin, lines, from, to, tolerance_, openEnds);
}

}  // namespace airshape::structure
