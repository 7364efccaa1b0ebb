#pragma once

#include <optional>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

#include "airshape/named_shape.h"

namespace airshape::controlsurfaces {

/// The wing's faces a device is made of: its component segment's upper and lower skin and the
/// wing's blunt trailing edge (empty where the trailing edge is sharp), in the global frame.
struct WingSkins {
  TopoDS_Shape upper, lower, trailingEdge;
};

/// Where a device lies of its borders' outlines, which run across the wing: aft of them
/// (trailing-edge devices), ahead of them (leading-edge devices), or, for a spoiler's panel,
/// above the line inside the wing between the panel's front and back; or the whole chord
/// between the borders, for a trailing-edge device cut at the wing's own leading edge (an
/// all-moving surface), whose straight outlines only touch the skins there.
enum class OutlineKind { Aft, Ahead, Panel, WholeChord };

/// What the device's faces are called: "<uID>/" and the face's part.
struct DeviceFaceNames {
  std::string prefix;       ///< "<uID>/"
  std::string cutterFaces;  ///< the part the cutter's faces inside the wing become
};

/// The device at rest (the wing in common with the ruled solid between its inner and outer
/// border) made from the wing's faces without a Boolean operation. Both borders' outlines
/// (closedOutlines) are of one kind with corners in the same order: four straight edges (a straight
/// cut across the wing, a panel) or a shaped edge between the skins followed by five straight
/// ones (a rounded nose, a hollow back), whose ruled face between the borders is `shapedSide`
/// (the cutter's). `cutter` is the ruled solid itself, which tells which pieces of the skins
/// a device ahead of its outlines keeps (the lines across its rounded nose fan out from inside
/// the wing). The skins are split along the solid's sides (geometry::skinPiecesWhere), the
/// sides inside the wing trimmed where their lines meet the skins, each border's side made the
/// plane face the other faces leave open there, and all sewn into a solid. `tolerance` is how
/// closely the cut curves follow the true crossings (a length). Nothing where this does not
/// apply; the caller then cuts the device by a Boolean operation.
std::optional<NamedShape> deviceFromSkins(const WingSkins& skins, OutlineKind kind, const TopoDS_Wire& inner,
                                          const TopoDS_Wire& outer, const TopoDS_Shape& cutter,
                                          const TopoDS_Face& shapedSide, const DeviceFaceNames& names,
                                          double tolerance);

}  // namespace airshape::controlsurfaces
