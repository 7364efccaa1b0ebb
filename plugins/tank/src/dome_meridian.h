#pragma once

#include <vector>

#include <Geom_Curve.hxx>

namespace airshape::tank {

/// The meridian of a vessel's front dome in the x-z plane (z is the radius, x runs along the
/// vessel's axis): curves from the axis at x = 0 to the cylinder's edge at (depth, 0, R).
/// Revolved about the x axis it is the dome; mirrored behind the cylinder, the rear dome.
struct DomeMeridian {
  std::vector<Handle(Geom_Curve)> curves;
  double depth = 0.0;
};

/// A half ellipsoid of depth halfAxisFraction * R (a sphere for 1, a flat end for 0).
DomeMeridian ellipsoidDome(double cylinderRadius, double halfAxisFraction);

/// A torispherical dome: a spherical crown of radius dishRadius (> R) joined tangentially to
/// the cylinder by a knuckle, a torus of radius knuckleRadius (0 < knuckleRadius < R).
DomeMeridian torisphericalDome(double cylinderRadius, double dishRadius, double knuckleRadius);

/// An isotensoid dome (isotensoid_meridian.h) closed by a flat lid over its polar opening
/// (0 < polarOpeningRadius < R).
DomeMeridian isotensoidDome(double cylinderRadius, double polarOpeningRadius);

}  // namespace airshape::tank
