#include "airshape/geometry/bspline_basis.h"

#include <cmath>
#include <numeric>

#include <BSplCLib.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <math_Matrix.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

TColStd_Array1OfReal occKnots(const KnotVector& space) {
  TColStd_Array1OfReal knots(1, static_cast<int>(space.knots.size()));
  for (std::size_t i = 0; i < space.knots.size(); ++i) knots(static_cast<int>(i) + 1) = space.knots[i];
  return knots;
}

TColStd_Array1OfInteger occMultiplicities(const KnotVector& space) {
  TColStd_Array1OfInteger multiplicities(1, static_cast<int>(space.multiplicities.size()));
  for (std::size_t i = 0; i < space.multiplicities.size(); ++i)
    multiplicities(static_cast<int>(i) + 1) = space.multiplicities[i];
  return multiplicities;
}

int KnotVector::poleCount() const {
  const int sum = std::accumulate(multiplicities.begin(), multiplicities.end(), 0);
  return periodic ? sum - multiplicities.back() : sum - degree - 1;
}

KnotVector averagedKnots(const std::vector<double>& parameters, int degree) {
  const int count = static_cast<int>(parameters.size());
  if (count < degree + 1)
    throw Error(ErrorCode::InvalidArgument, "interpolation of degree " + std::to_string(degree) + " needs at least " +
                                                std::to_string(degree + 1) + " points, got " + std::to_string(count));
  KnotVector space;
  space.degree = degree;
  space.knots.push_back(parameters.front());
  space.multiplicities.push_back(degree + 1);
  for (int j = 1; j < count - degree; ++j) {
    double sum = 0.0;
    for (int i = j; i < j + degree; ++i) sum += parameters[static_cast<std::size_t>(i)];
    space.knots.push_back(sum / degree);
    space.multiplicities.push_back(1);
  }
  space.knots.push_back(parameters.back());
  space.multiplicities.push_back(degree + 1);
  return space;
}

KnotVector uniformKnots(double first, double last, int poleCount, int degree) {
  KnotVector space;
  space.degree = degree;
  const int segments = poleCount - degree;
  for (int i = 0; i <= segments; ++i) {
    space.knots.push_back(first + (last - first) * i / segments);
    space.multiplicities.push_back(i == 0 || i == segments ? degree + 1 : 1);
  }
  return space;
}

KnotVector periodicInterpolationKnots(const std::vector<double>& parameters, int degree) {
  KnotVector space;
  space.degree = degree;
  space.periodic = true;
  const std::size_t count = parameters.size();  // points + 1: the last closes the period
  const double period = parameters.back() - parameters.front();
  if (degree % 2 == 1) {
    space.knots = parameters;
  } else {
    for (std::size_t i = 0; i + 1 < count; ++i) space.knots.push_back(0.5 * (parameters[i] + parameters[i + 1]));
    space.knots.push_back(space.knots.front() + period);
  }
  space.multiplicities.assign(space.knots.size(), 1);
  return space;
}

KnotVector periodicUniformKnots(double first, double last, int poleCount, int degree) {
  KnotVector space;
  space.degree = degree;
  space.periodic = true;
  for (int i = 0; i <= poleCount; ++i) space.knots.push_back(first + (last - first) * i / poleCount);
  space.multiplicities.assign(space.knots.size(), 1);
  return space;
}

namespace {

/// Calls visit(row, column, value) for every non-zero basis value at the parameters.
template <class Visit>
void forEachBasisValue(const KnotVector& space, const std::vector<double>& parameters, int derivative, Visit visit) {
  const TColStd_Array1OfReal knots = occKnots(space);
  const TColStd_Array1OfInteger multiplicities = occMultiplicities(space);
  TColStd_Array1OfReal flat(1, BSplCLib::KnotSequenceLength(multiplicities, space.degree, space.periodic));
  BSplCLib::KnotSequence(knots, multiplicities, space.degree, space.periodic, flat);

  const int poles = space.poleCount();
  const double period = space.last() - space.first();
  math_Matrix basis(1, derivative + 1, 1, space.degree + 1);
  for (std::size_t row = 0; row < parameters.size(); ++row) {
    double t = parameters[row];
    if (space.periodic) t = space.first() + std::fmod(std::fmod(t - space.first(), period) + period, period);
    int firstIndex = 0;
    BSplCLib::EvalBsplineBasis(derivative, space.degree + 1, flat, t, firstIndex, basis, space.periodic);
    for (int k = 0; k <= space.degree; ++k) {
      int column = firstIndex - 1 + k;
      if (space.periodic) column = ((column % poles) + poles) % poles;
      visit(static_cast<Eigen::Index>(row), column, basis(derivative + 1, k + 1));
    }
  }
}

}  // namespace

Eigen::MatrixXd basisMatrix(const KnotVector& space, const std::vector<double>& parameters, int derivative) {
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(parameters.size()), space.poleCount());
  forEachBasisValue(space, parameters, derivative,
                    [&](Eigen::Index row, int column, double value) { matrix(row, column) += value; });
  return matrix;
}

Eigen::SparseMatrix<double> sparseBasisMatrix(const KnotVector& space, const std::vector<double>& parameters) {
  std::vector<Eigen::Triplet<double>> entries;
  forEachBasisValue(space, parameters, 0, [&](Eigen::Index row, int column, double value) {
    if (value != 0.0) entries.emplace_back(static_cast<int>(row), column, value);
  });
  Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(parameters.size()), space.poleCount());
  matrix.setFromTriplets(entries.begin(), entries.end());  // sums the wrapped duplicates of periodic spaces
  return matrix;
}

}  // namespace airshape::geometry
