#pragma once

#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>

namespace airshape::geometry {

/// The knots of a B-spline space: distinct values with multiplicities, its degree and
/// whether it is periodic (then the first and last knot values bound one period).
struct KnotVector {
  std::vector<double> knots;
  std::vector<int> multiplicities;
  int degree = 3;
  bool periodic = false;

  /// Number of control points (basis functions) of the space.
  int poleCount() const;
  double first() const { return knots.front(); }
  double last() const { return knots.back(); }
};

/// The distinct knots and their multiplicities as OCCT arrays (1-based), as its B-spline
/// classes take them.
TColStd_Array1OfReal occKnots(const KnotVector& space);
TColStd_Array1OfInteger occMultiplicities(const KnotVector& space);

/// Clamped knots for interpolation at `parameters` by averaging (de Boor): interior knot j
/// is the mean of `degree` consecutive parameters, so the system matrix is well posed.
KnotVector averagedKnots(const std::vector<double>& parameters, int degree);
/// Clamped knots spread evenly over [first, last] for `poleCount` control points.
KnotVector uniformKnots(double first, double last, int poleCount, int degree);
/// Periodic knots for interpolating the closed point list at `parameters` (the last
/// parameter closes the period): knots at the parameters for odd degrees, and at their
/// midpoints for even degrees (the shifting method), where knots at the parameters would
/// make the system singular.
KnotVector periodicInterpolationKnots(const std::vector<double>& parameters, int degree);
/// Periodic knots spread evenly over one period for `poleCount` control points.
KnotVector periodicUniformKnots(double first, double last, int poleCount, int degree);

/// Matrix of basis function values (or their `derivative`-th derivatives):
/// row j, column i holds B_i^(derivative)(parameters[j]). Periodic spaces wrap around.
Eigen::MatrixXd basisMatrix(const KnotVector& space, const std::vector<double>& parameters, int derivative = 0);
/// The same matrix in sparse form: each row has at most degree + 1 non-zeros.
Eigen::SparseMatrix<double> sparseBasisMatrix(const KnotVector& space, const std::vector<double>& parameters);

}  // namespace airshape::geometry
