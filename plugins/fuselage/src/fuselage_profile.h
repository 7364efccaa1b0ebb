#pragma once

#include <vector>

#include <Eigen/Geometry>
#include <Geom_BSplineCurve.hxx>

#include "airshape/problem.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::fuselage {

/// A fuselage profile in the y-z plane as one B-spline curve whose parameter over [0, 1] is
/// zeta, starting at the first point of the list. A closed profile (first and last point
/// within 0.5 % of its size) is periodic and smooth across its seam; an open one (a half
/// fuselage) is closed by a straight edge in the loft.
struct FuselageProfile {
  Handle(Geom_BSplineCurve) curve;
  bool closed = true;
  /// The reference's <symmetry>half</symmetry>: a half interpolated as its mirrored whole.
  /// Its relative circumference leaves out the closing edge.
  bool mirroredHalf = false;
  /// The points of a point list as given (empty for a standard profile; a mirrored half
  /// without its mirror image).
  std::vector<gp_Pnt> points;
  /// The length guide curve profiles are scaled by for a standard profile: the rectangle's
  /// height ratio, 1 for a superellipse (unscaled, as the reference has it).
  double standardGuideScale = 1.0;
  /// What was odd but buildable about the definition (points whose outline crosses itself by
  /// less than the tolerance), each naming its CPACS path.
  Problems warnings;

  /// The length guide curve profiles are scaled by where this profile is placed by
  /// `transform`: for a point list, from the middle of its first and last point to the
  /// point farthest from there (its "diameter line"), in global coordinates; for a mirrored
  /// half, from its first point to its last (both on the symmetry plane).
  double guideScale(const Eigen::Affine3d& transform) const;

  /// Throws Error naming the profile's CPACS path for a definition that gives no curve.
  static FuselageProfile fromDefinition(const schema::ProfileGeometryType& definition);
};

}  // namespace airshape::fuselage
