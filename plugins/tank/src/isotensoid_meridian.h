#pragma once

#include <Geom_BSplineCurve.hxx>

namespace airshape::tank {

/// The meridian of an isotensoid dome (a dome of filaments wound along geodesics that carry
/// equal tension) on a cylinder of radius `cylinderRadius` with a polar opening of radius
/// `polarOpeningRadius`, in the x-z plane (z is the radius): from the polar opening at x = 0
/// to the cylinder at x = its depth. Netting theory gives the meridian's curvature radius
/// rho = r / (cos(phi) (2 - tan^2 alpha)), with Clairaut's sin(alpha) = r0 / r; it is
/// stepped from the cylinder in 50 steps of the slope angle phi, as the reference steps it,
/// until the winding angle or the radius reach their limits, continued straight to the
/// opening, and approximated by a B-spline through the steps.
Handle(Geom_BSplineCurve) isotensoidMeridian(double cylinderRadius, double polarOpeningRadius);

}  // namespace airshape::tank
