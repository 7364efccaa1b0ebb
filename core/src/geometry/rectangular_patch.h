#pragma once

#include <optional>
#include <vector>

#include <Geom_Surface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopoDS_Face.hxx>

namespace airshape::geometry {

/// A face that is a whole rectangle of its surface's parameters (bounded by four iso-lines),
/// on a surface whose measures Gauss rules take span by span: on each span between `uBreaks`
/// (`vBreaks`) the integrands are polynomials of the stated degree in that parameter, or so
/// smooth that a rule for that degree leaves errors far below rounding.
///
/// - a polynomial B-spline surface: its knots and degrees;
/// - a surface turned about an axis (of revolution of a polynomial B-spline curve or a line, a
///   cylinder, a cone, a sphere, a torus): along the angle u, eighths of a turn, on which the
///   integrands are trigonometric polynomials of low order (taken as degree 6: ten points for a
///   volume, sixteen for an area); along v, the curve's knots and degree (a sphere's and a
///   torus's v is an angle too).
struct RectangularPatch {
  Handle(Geom_Surface) surface;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  std::vector<double> uBreaks, vBreaks;
  int uDegree = 0, vDegree = 0;
};

/// The distinct knots inside [from, to], with the ends: the spans a B-spline's integrands are
/// polynomials on.
std::vector<double> knotBreaks(const TColStd_Array1OfReal& knots, double from, double to);

/// The face as such a patch; nothing for any other face (trimmed, or on another surface).
std::optional<RectangularPatch> rectangularPatch(const TopoDS_Face& face);

}  // namespace airshape::geometry
