#pragma once

#include <optional>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

#include "airshape/named_shape.h"

namespace airshape::controlsurfaces {

/// The wing's faces a device is made of: its component segment's upper and lower skin and the
/// wing's blunt trailing edge (empty where the trailing edge is sharp), in the global frame.
struct WingSkins {
  TopoDS_Shape upper, lower, trailingEdge;
};

/// How the straight outline of a border lies across the wing: a straight cut from below the
/// wing to above it with the device aft of it (trailing-edge devices) or ahead of it
/// (leading-edge devices), or a spoiler's panel: the upper skin above a line inside the wing.
enum class StraightOutline { CutAft, CutAhead, Panel };

/// What the device's faces are called: "<uID>/" and the face's part.
struct DeviceFaceNames {
  std::string prefix;       ///< "<uID>/"
  std::string cutterFaces;  ///< the part the cutter's faces inside the wing become
};

/// The device at rest (the wing in common with the ruled solid between its inner and outer
/// border) made from the wing's faces without a Boolean operation, where both borders are
/// straight outlines of the same kind with four corners each (borderWire's straight cut or
/// panel, their corners in the same order): the skins split along the solid's sides
/// (geometry::skinPiecesWhere), the solid's sides inside the wing trimmed where their lines
/// meet the skins, each border's side the plane face the other faces leave open there, all
/// sewn into a solid. `tolerance` is how closely the cut curves follow the true crossings (a
/// length). Nothing where this does not apply; the caller then cuts the device by a Boolean
/// operation.
std::optional<NamedShape> deviceFromSkins(const WingSkins& skins, StraightOutline outline, const TopoDS_Wire& inner,
                                          const TopoDS_Wire& outer, const DeviceFaceNames& names, double tolerance);

}  // namespace airshape::controlsurfaces
