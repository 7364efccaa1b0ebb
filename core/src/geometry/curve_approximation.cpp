#include "airshape/geometry/curve_approximation.h"

#include <Eigen/SparseLU>

#include "airshape/error.h"

namespace airshape::geometry {

PoleMatrix approximatePoles(const KnotVector& space, const std::vector<double>& parameters, const PoleMatrix& points,
                            const InterpolationConstraints& constraints) {
  // The system is banded (each basis function lives on degree + 1 knot spans), so it is
  // assembled and solved in sparse form: linear in the number of control points.
  const Eigen::SparseMatrix<double> samples = sparseBasisMatrix(space, parameters);
  const Eigen::Index poles = samples.cols();
  const auto pinned = static_cast<Eigen::Index>(constraints.parameters.size());
  const Eigen::Index fixed = pinned + constraints.seamContinuity;
  const Eigen::SparseMatrix<double> normal = samples.transpose() * samples;
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index column = 0; column < normal.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator it(normal, column); it; ++it)
      entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
  Eigen::MatrixXd rightSide = Eigen::MatrixXd::Zero(poles + fixed, 3);
  rightSide.topRows(poles) = samples.transpose() * points;
  auto addConstraintEntry = [&](Eigen::Index row, Eigen::Index pole, double value) {
    if (value == 0.0) return;
    entries.emplace_back(static_cast<int>(poles + row), static_cast<int>(pole), value);
    entries.emplace_back(static_cast<int>(pole), static_cast<int>(poles + row), value);
  };
  if (pinned > 0) {
    const Eigen::SparseMatrix<double> rows = sparseBasisMatrix(space, constraints.parameters);
    for (Eigen::Index column = 0; column < rows.outerSize(); ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator it(rows, column); it; ++it)
        addConstraintEntry(it.row(), it.col(), it.value());
    rightSide.block(poles, 0, pinned, 3) = constraints.points;
  }
  for (int derivative = 1; derivative <= constraints.seamContinuity; ++derivative) {
    // The derivative at the start minus the one at the end is zero.
    const Eigen::MatrixXd start = basisMatrix(space, {space.first()}, derivative);
    const Eigen::MatrixXd end = basisMatrix(space, {space.last()}, derivative);
    for (Eigen::Index pole = 0; pole < poles; ++pole)
      addConstraintEntry(pinned + derivative - 1, pole, start(0, pole) - end(0, pole));
  }
  Eigen::SparseMatrix<double> system(poles + fixed, poles + fixed);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(system);
  if (solver.info() != Eigen::Success)
    throw Error(ErrorCode::InvalidArgument,
                "the approximation system is singular: " + std::to_string(parameters.size()) + " samples and " +
                    std::to_string(fixed) + " constraints for " + std::to_string(poles) + " control points");
  const Eigen::MatrixXd solution = solver.solve(rightSide);
  return solution.topRows(poles);
}

}  // namespace airshape::geometry
