#pragma once

#include <vector>

#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::controlsurfaces {

/// What a device's path gives at one control parameter: the hinge line's rotation (degrees)
/// and the translations of its inner and outer hinge point (the outer one's y is the inner
/// one's, as the reference library has it).
struct StepValues {
  double rotation = 0.0;
  gp_XYZ innerTranslation, outerTranslation;
};

/// The path's values at `controlParameter`, interpolated piecewise linearly between its
/// steps (held at the first and last step outside them).
StepValues stepValuesAt(const schema::ControlSurfaceStepsType& steps, double controlParameter);

/// The rigid motion of a device whose hinge line runs from `inner` to `outer` at rest, for the
/// step values `values` (QUERY-components §3.4): the hinge points move by their translations,
/// the device turns about the moved hinge line by the rotation (positive: trailing edge
/// down), and slides along it so that the moved hinge line keeps its length centred.
/// Throws Error for a hinge line without length or parallel to x-z (no hinge frame).
gp_Trsf hingeMotion(const gp_Pnt& inner, const gp_Pnt& outer, const StepValues& values);

/// The rotation angle of a rigid motion's rotation, in degrees, in [0, 180].
double rotationAngle(const gp_Trsf& motion);

}  // namespace airshape::controlsurfaces
