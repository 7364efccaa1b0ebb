#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <Bnd_Box.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/geometry/skin_section.h"
#include "structure_frame.h"

namespace airshape::structure {

/// Plane pieces of structure inside a control device (its ribs and the plane pieces of its
/// spar webs), made without a Boolean operation. The device at rest is its wing in common with
/// a simple ruled solid (its cutter), and its own faces are trimmed pieces of the wing's skins,
/// which the trace along lines does not take; so in the piece's plane, the wing's section
/// (traced from the component segment's untrimmed skins between the piece's ends) is put in
/// common with the cutter's section (ruled_solid_section.h), in the plane's own coordinates
/// (plane_region.h).
class DeviceSection {
 public:
  /// For the structure of a device with a cutter (StructureFrame::deviceCutter).
  DeviceSection(const StructureFrame& frame, TopoDS_Shape cutter);

  /// The piece's faces in the plane of `lines` between its ends, an open end closed as
  /// `openEnds` says (skin_section.h); nothing where the skins or the cutter do not allow it
  /// or nothing of the plane lies in the device (the caller then cuts by a Boolean common,
  /// which tells that too).
  std::optional<std::vector<TopoDS_Face>> faces(const geometry::CrossingLines& lines, const geometry::CrossingEnd& from,
                                                const geometry::CrossingEnd& to, geometry::OpenEnds openEnds) const;

 private:
  /// The wing's section between the ends, an open end traced only as far as the device's box
  /// reaches along the lines (a flap's rib need not be traced round the wing's leading edge),
  /// closed straight outside the device where the wing reaches beyond the box.
  std::optional<TopoDS_Face> wingSection(const geometry::CrossingLines& lines, geometry::CrossingEnd from,
                                         geometry::CrossingEnd to, geometry::OpenEnds openEnds) const;

  const StructureFrame& frame_;
  TopoDS_Shape cutter_;
  double tolerance_;
  /// The component segment's upper and lower skin, and the box that holds the device: fetched
  /// for the first piece.
  mutable std::optional<std::pair<TopoDS_Shape, TopoDS_Shape>> wingSkins_;
  mutable std::optional<Bnd_Box> deviceBox_;
};

}  // namespace airshape::structure
