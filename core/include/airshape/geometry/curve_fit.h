#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

namespace airshape::geometry {

/// A point of a curve known only by evaluation (where a plane crosses a skin or a ruled face):
/// its parameter, the point, the derivative there, and where it lies in the parameters of the
/// surface it was found on (the guess for the Newton steps of samples next to it).
struct CurveSample {
  double t = 0.0;
  gp_Pnt point;
  gp_Vec tangent;
  gp_Pnt2d where;
};

/// Evaluates the curve at t, given two samples on either side of t (for their `where`);
/// nothing when it cannot.
using CurveSampler =
    std::function<std::optional<CurveSample>(double t, const CurveSample& before, const CurveSample& after)>;

/// The straight line from one point to another as a B-spline of degree 1, parametrised by
/// length.
Handle(Geom_BSplineCurve) straightCurve(const gp_Pnt& from, const gp_Pnt& to);

/// The cubic B-spline through the samples (at their parameters, ascending), with their
/// derivatives at every sample (a Hermite cubic) or only at the ends (a C2 cubic); null when
/// OCCT cannot make it.
Handle(Geom_BSplineCurve) cubicThrough(const std::vector<CurveSample>& samples, bool everyDerivative);

/// The cubic B-spline through samples of a curve from `first` to `last` (their parameter, point
/// and `where`), parametrised like the curve and ending exactly at their points: starting from four even intervals, an
/// interval is halved where the cubic Hermite interpolant of its ends strays from the curve's middle by more than
/// `tolerance`, so that samples are dense only where the curve bends. The C2 cubic through the samples (half the poles,
/// and one piece for OCCT's intersections), with samples added where it strays at an interval's middle, else the
/// Hermite cubic; null when a sample cannot be made.
Handle(Geom_BSplineCurve)
    fittedCurve(const CurveSampler& sample, const CurveSample& first, const CurveSample& last, double tolerance);

}  // namespace airshape::geometry
