#include "airshape/geometry/chebyshev_approximation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>

namespace airshape::geometry {

namespace {

/// Polynomial coefficients, lowest power first.
using Polynomial = std::vector<double>;

/// One accepted piece: its parameter range and the Chebyshev coefficients of x, y and z
/// through the approximation degree.
struct ChebyshevPiece {
  double first = 0.0, last = 0.0;
  std::vector<gp_XYZ> coefficients;
};

/// Chebyshev coefficients c_0 … c_{n−1} of f on [a, b] from its values at the n Chebyshev
/// nodes: f ≈ Σ c_j T_j(2s − 1) with s = (t − a)/(b − a).
std::vector<gp_XYZ> chebyshevCoefficients(const std::function<gp_Pnt(double)>& f, double a, double b, int n) {
  std::vector<gp_XYZ> values(n);
  for (int k = 0; k < n; ++k) {
    const double node = std::cos(M_PI * (k + 0.5) / n);
    values[k] = f(a + (node + 1.0) / 2.0 * (b - a)).XYZ();
  }
  std::vector<gp_XYZ> coefficients(n, gp_XYZ(0, 0, 0));
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k < n; ++k) coefficients[j] += values[k] * (2.0 / n * std::cos(M_PI * j * (k + 0.5) / n));
  }
  coefficients[0] *= 0.5;
  return coefficients;
}

void approximatePieces(const std::function<gp_Pnt(double)>& f, double a, double b, int depth,
                       const ChebyshevSettings& settings, std::vector<ChebyshevPiece>& pieces) {
  const int degree = settings.degree;
  std::vector<gp_XYZ> coefficients = chebyshevCoefficients(f, a, b, degree + 5);
  gp_XYZ tail(0, 0, 0);  // the sums of |c_j| beyond the degree, per coordinate
  for (std::size_t j = degree + 1; j < coefficients.size(); ++j)
    tail += gp_XYZ(std::abs(coefficients[j].X()), std::abs(coefficients[j].Y()), std::abs(coefficients[j].Z()));
  // Each coordinate is judged on its own (the largest tail), not their vector: the
  // reference's superellipses are split so (docs/conformance.md); its airfoils do not
  // tell the two apart.
  const double error = std::max({tail.X(), tail.Y(), tail.Z()});
  if (error < settings.tolerance || depth >= settings.maxDepth) {
    coefficients.resize(degree + 1);
    pieces.push_back({a, b, std::move(coefficients)});
    return;
  }
  const double middle = a + 0.5 * (b - a);
  approximatePieces(f, a, middle, depth + 1, settings, pieces);
  approximatePieces(f, middle, b, depth + 1, settings, pieces);
}

/// T_0 … T_degree of (2s − 1) as polynomials in s.
std::vector<Polynomial> shiftedChebyshevPolynomials(int degree) {
  std::vector<Polynomial> t(degree + 1, Polynomial(degree + 1, 0.0));
  t[0][0] = 1.0;
  if (degree >= 1) t[1] = Polynomial(degree + 1, 0.0), t[1][0] = -1.0, t[1][1] = 2.0;
  for (int j = 2; j <= degree; ++j)  // T_j = 2(2s − 1)·T_{j−1} − T_{j−2}
    for (int k = 0; k <= degree; ++k)
      t[j][k] = 2.0 * (2.0 * (k > 0 ? t[j - 1][k - 1] : 0.0) - t[j - 1][k]) - t[j - 2][k];
  return t;
}

/// The Bézier control points of one piece's polynomial on its range.
std::vector<gp_XYZ> bezierPoles(const ChebyshevPiece& piece, const std::vector<Polynomial>& chebyshev) {
  const int degree = static_cast<int>(piece.coefficients.size()) - 1;
  std::vector<gp_XYZ> monomial(degree + 1, gp_XYZ(0, 0, 0));
  for (int j = 0; j <= degree; ++j)
    for (int k = 0; k <= degree; ++k) monomial[k] += piece.coefficients[j] * chebyshev[j][k];
  // Bernstein coefficient i = Σ_{k ≤ i} C(i, k)/C(degree, k) · a_k.
  std::vector<gp_XYZ> poles(degree + 1, gp_XYZ(0, 0, 0));
  for (int i = 0; i <= degree; ++i) {
    double ratio = 1.0;  // C(i, k)/C(degree, k), starting at k = 0
    for (int k = 0; k <= i; ++k) {
      poles[i] += monomial[k] * ratio;
      ratio *= static_cast<double>(i - k) / static_cast<double>(degree - k);
    }
  }
  return poles;
}

}  // namespace

Handle(Geom_BSplineCurve) approximateByChebyshevPieces(const std::function<gp_Pnt(double)>& f, double first,
                                                       double last, const ChebyshevSettings& settings) {
  const int degree = settings.degree;
  std::vector<ChebyshevPiece> pieces;
  approximatePieces(f, first, last, 1, settings, pieces);
  const std::vector<Polynomial> chebyshev = shiftedChebyshevPolynomials(degree);

  const int count = static_cast<int>(pieces.size());
  TColgp_Array1OfPnt poles(1, 2 + count * (degree - 1));
  TColStd_Array1OfReal knots(1, count + 1);
  TColStd_Array1OfInteger multiplicities(1, count + 1);
  int pole = 1;
  poles(pole++) = f(first);
  for (int i = 0; i < count; ++i) {
    const std::vector<gp_XYZ> bezier = bezierPoles(pieces[i], chebyshev);
    for (int j = 1; j < degree; ++j) poles(pole++) = gp_Pnt(bezier[j]);
    knots(i + 1) = pieces[i].first;
    multiplicities(i + 1) = i == 0 ? degree + 1 : degree - 1;
  }
  poles(pole) = f(last);
  knots(count + 1) = last;
  multiplicities(count + 1) = degree + 1;
  return new Geom_BSplineCurve(poles, knots, multiplicities, degree);
}

}  // namespace airshape::geometry
