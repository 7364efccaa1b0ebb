#pragma once

#include <vector>

#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>

namespace airshape::geometry {

/// Arc length along a B-spline curve, measured from its first parameter. The length up to
/// every knot is integrated once (Gauss–Legendre on each knot span, where the speed is smooth;
/// where it changes much, halving the span until two rules agree to 1e-14); a length or a
/// parameter is then found
/// within its span alone. Answers agree with OCCT's GCPnts_AbscissaPoint to its tolerance at a
/// small part of its cost, which integrates from the start again for every answer.
class ArcLength {
 public:
  explicit ArcLength(const Handle(Geom_BSplineCurve) & curve);

  /// The whole curve's length.
  double total() const { return lengthToKnot_.back(); }
  /// The length from the first parameter to `t` (clamped to the curve's range).
  double lengthAt(double t) const;
  /// The parameter at `length` from the first parameter (clamped to [0, total()]).
  double parameterAt(double length) const;

 private:
  double speed(double t) const;
  double integral(double from, double to) const;
  std::size_t spanOf(double t) const;

  GeomAdaptor_Curve curve_;
  std::vector<double> knots_;         ///< distinct knots, the ends included
  std::vector<double> lengthToKnot_;  ///< the length up to each of them
};

}  // namespace airshape::geometry
