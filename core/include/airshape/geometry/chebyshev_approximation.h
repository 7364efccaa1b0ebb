#pragma once

#include <functional>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>

namespace airshape::geometry {

/// How closely, and how finely at most, a function is turned into a curve.
struct ChebyshevSettings {
  int degree = 3;
  /// Largest accepted estimate of the error on a piece (per coordinate, the sum of the
  /// Chebyshev coefficients beyond `degree`, four more of them computed for the estimate;
  /// the largest of the three).
  double tolerance = 1e-5;
  /// The whole range is depth 1; a piece at this depth is accepted whatever its error.
  int maxDepth = 10;
};

/// A B-spline of `settings.degree` over [first, last] that follows the curve `f` by
/// piecewise Chebyshev approximation: on each piece the truncated Chebyshev series through
/// degree+5 Chebyshev nodes, halved until its error estimate is small enough; each piece as
/// a Bézier segment whose end points are moved onto `f`; the pieces joined with knots of
/// multiplicity degree−1 that leave out the shared end points, so the result is C1 at the
/// joins and passes through f(first) and f(last). The parameter is that of `f`. The
/// deviation from `f` is of the order of the tolerance (the estimate is no bound, and the
/// joins move points near them by about as much).
///
/// The reference library turns its analytic airfoils (CST, NACA) into curves this way; the
/// same construction gives the same curves, so points at a given xsi agree.
Handle(Geom_BSplineCurve) approximateByChebyshevPieces(const std::function<gp_Pnt(double)>& f, double first,
                                                       double last, const ChebyshevSettings& settings);

}  // namespace airshape::geometry
