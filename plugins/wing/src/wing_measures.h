#pragma once

#include <string>

#include <gp_Pnt.hxx>

#include "wing_geometry.h"

namespace airshape::wing {

/// The sum over segments of the chord quadrilaterals projected onto a plane ("x-y", "x-z"
/// or "y-z"): half the cross product of their diagonals (not mirrored).
double referenceArea(const WingGeometry& wing, const std::string& plane);

/// The mean aerodynamic chord and the leading-edge point of the MAC station.
struct MeanAerodynamicChord {
  double length = 0.0;
  gp_Pnt leadingEdge;
};
MeanAerodynamicChord meanAerodynamicChord(const WingGeometry& wing);

/// The span: the extent along the major axis of every airfoil of the wing (and of their
/// mirror images when the wing is mirrored). `symmetry` is "none", "x-y", "x-z" or "y-z";
/// `unparented` takes the wing's points to where they would be without the parent's
/// translation (the reference measures there).
double span(const WingGeometry& wing, const std::string& symmetry, const model::Transform& unparented);

}  // namespace airshape::wing
