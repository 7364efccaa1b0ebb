#include "dome_meridian.h"

#include <cmath>
#include <sstream>
#include <string>

#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <gp_Elips.hxx>

#include "airshape/error.h"
#include "isotensoid_meridian.h"

namespace airshape::tank {

namespace {

/// A point of the x-z plane: along the axis, and the radius.
gp_Pnt meridianPoint(double x, double radius) { return {x, 0.0, radius}; }

Handle(Geom_Curve) segment(const gp_Pnt& from, const gp_Pnt& to) {
  return Handle(Geom_Curve)(GC_MakeSegment(from, to).Value());
}

/// The arc of a circle about `centre` from `from` to `to` (less than half a turn).
Handle(Geom_Curve) arc(const gp_Pnt& centre, const gp_Pnt& from, const gp_Pnt& to) {
  const gp_Vec a(centre, from), b(centre, to);
  const gp_Vec bisector = a.Normalized() + b.Normalized();
  const gp_Pnt middle = centre.Translated(bisector.Normalized() * a.Magnitude());
  return Handle(Geom_Curve)(GC_MakeArcOfCircle(from, middle, to).Value());
}

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

DomeMeridian ellipsoidDome(double cylinderRadius, double halfAxisFraction) {
  if (halfAxisFraction < 0.0)
    throw Error(ErrorCode::InvalidModel, "the half axis fraction " + number(halfAxisFraction) + " is negative");
  const double depth = cylinderRadius * halfAxisFraction;
  const gp_Pnt apex = meridianPoint(0.0, 0.0), rim = meridianPoint(depth, cylinderRadius);
  if (depth == 0.0) return {{segment(apex, rim)}, 0.0};  // a flat end
  // The quarter of the ellipse about (depth, 0) from the apex to the rim; gp_Elips wants its
  // major axis first.
  const gp_Pnt centre = meridianPoint(depth, 0.0);
  if (depth >= cylinderRadius) {
    const gp_Elips ellipse(gp_Ax2(centre, gp_Dir(0, 1, 0), gp_Dir(-1, 0, 0)), depth, cylinderRadius);
    return {{new Geom_TrimmedCurve(new Geom_Ellipse(ellipse), 0.0, M_PI / 2)}, depth};
  }
  const gp_Elips ellipse(gp_Ax2(centre, gp_Dir(0, -1, 0), gp_Dir(0, 0, 1)), cylinderRadius, depth);
  Handle(Geom_Curve) rimToApex = new Geom_TrimmedCurve(new Geom_Ellipse(ellipse), 0.0, M_PI / 2);
  return {{rimToApex->Reversed()}, depth};
}

DomeMeridian torisphericalDome(double cylinderRadius, double dishRadius, double knuckleRadius) {
  if (dishRadius <= cylinderRadius)
    throw Error(ErrorCode::InvalidModel, "the dish radius " + number(dishRadius) +
                                             " must be larger than the cylinder radius " + number(cylinderRadius));
  if (knuckleRadius <= 0.0 || knuckleRadius >= cylinderRadius)
    throw Error(ErrorCode::InvalidModel, "the knuckle radius " + number(knuckleRadius) +
                                             " must lie between 0 and the cylinder radius " + number(cylinderRadius));
  // The knuckle's centre lies on the crown's sphere shrunk by the knuckle radius (the two
  // touch from inside), at the knuckle radius from the cylinder.
  const double knuckleCentreRadius = cylinderRadius - knuckleRadius;
  const double depth =
      dishRadius - std::sqrt(std::pow(dishRadius - knuckleRadius, 2) - knuckleCentreRadius * knuckleCentreRadius);
  const gp_Pnt crownCentre = meridianPoint(dishRadius, 0.0);
  const gp_Pnt knuckleCentre = meridianPoint(depth, knuckleCentreRadius);
  // Where they touch: on the line from the crown's centre through the knuckle's.
  const gp_Pnt touch =
      crownCentre.Translated(gp_Vec(crownCentre, knuckleCentre) * (dishRadius / (dishRadius - knuckleRadius)));
  return {{arc(crownCentre, meridianPoint(0.0, 0.0), touch),
           arc(knuckleCentre, touch, meridianPoint(depth, cylinderRadius))},
          depth};
}

DomeMeridian isotensoidDome(double cylinderRadius, double polarOpeningRadius) {
  if (polarOpeningRadius <= 0.0 || polarOpeningRadius >= cylinderRadius)
    throw Error(ErrorCode::InvalidModel, "the polar opening radius " + number(polarOpeningRadius) +
                                             " must lie between 0 and the cylinder radius " + number(cylinderRadius));
  Handle(Geom_Curve) dome = isotensoidMeridian(cylinderRadius, polarOpeningRadius);
  const gp_Pnt opening = dome->Value(dome->FirstParameter()), rim = dome->Value(dome->LastParameter());
  return {{segment(meridianPoint(0.0, 0.0), opening), dome}, rim.X()};
}

}  // namespace airshape::tank
