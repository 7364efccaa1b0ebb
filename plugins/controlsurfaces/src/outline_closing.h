#pragma once

#include <vector>

#include <TopoDS_Wire.hxx>

#include "device_border.h"

namespace airshape::controlsurfaces {

/// The closed wires of the outlines one ruled solid runs through (a device's borders, or a
/// skin cut-out's), each in its border plane, in the same order. Two borders are closed outside
/// the wing so that the ruled faces between them there are planes, which OCCT's Boolean
/// operations intersect with the wing's skins many times faster than twisted ones (and most
/// such pairs meet nowhere): the far edges of both lie in one plane above the wing, one beyond
/// it and one below it; a spoiler's panels have their lids in one plane. The edges that leave
/// the wing keep their directions and (but for the second panel's back) their ends, so the ruled
/// faces that cross the skins are the ones each border closed alone would give. Where the
/// borders stand so that common planes would not close them well (a corner at a glancing angle
/// or come down near the wing, or past where the border planes meet), and for an airfoil or
/// more than two outlines, each is closed on its own: 5 of its chords along its chord and 5 of
/// its half-thicknesses above and below. A straight cut beside a rounded edge (a file that
/// shapes one border only) is closed as a rounded edge that is straight, with the same edges.
std::vector<TopoDS_Wire> closedOutlines(const std::vector<BorderOutline>& outlines);

}  // namespace airshape::controlsurfaces
