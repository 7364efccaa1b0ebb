#include "airshape/geometry/curve_approximation.h"

#include <algorithm>
#include <cmath>

#include <Eigen/SparseLU>
#include <GeomAdaptor_Curve.hxx>
#include <gp_Vec.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

namespace {

/// Solves approximation systems one after another, reusing the sparse LU's analysis of the
/// last system (its column ordering) when the next has the same pattern of non-zeros: the
/// parameter corrections of one fit move samples within their knot spans mostly, and the
/// analysis was half of each solve. The solutions are the same as with a fresh analysis.
class ApproximationSolver {
 public:
  PoleMatrix solve(const KnotVector& space, const std::vector<double>& parameters, const PoleMatrix& points,
                   const InterpolationConstraints& constraints);

 private:
  /// Analyses `system` unless the last one had its pattern, then factorises it.
  void factorise(const Eigen::SparseMatrix<double>& system);

  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver_;
  std::vector<int> outerStarts_, innerIndices_;  ///< the pattern last analysed
};

void ApproximationSolver::factorise(const Eigen::SparseMatrix<double>& system) {
  const auto columns = static_cast<std::size_t>(system.outerSize());
  const auto nonZeros = static_cast<std::size_t>(system.nonZeros());
  const bool samePattern = outerStarts_.size() == columns + 1 && innerIndices_.size() == nonZeros &&
                           std::equal(outerStarts_.begin(), outerStarts_.end(), system.outerIndexPtr()) &&
                           std::equal(innerIndices_.begin(), innerIndices_.end(), system.innerIndexPtr());
  if (!samePattern) {
    solver_.analyzePattern(system);
    outerStarts_.assign(system.outerIndexPtr(), system.outerIndexPtr() + columns + 1);
    innerIndices_.assign(system.innerIndexPtr(), system.innerIndexPtr() + nonZeros);
  }
  solver_.factorize(system);
}

PoleMatrix ApproximationSolver::solve(const KnotVector& space, const std::vector<double>& parameters,
                                      const PoleMatrix& points, const InterpolationConstraints& constraints) {
  // The system is banded (each basis function lives on degree + 1 knot spans), so it is
  // assembled and solved in sparse form: linear in the number of control points.
  const Eigen::SparseMatrix<double> samples = sparseBasisMatrix(space, parameters);
  const Eigen::Index poles = samples.cols();
  const auto pinned = static_cast<Eigen::Index>(constraints.parameters.size());
  const int firstSeamDerivative = constraints.freeSeam ? 0 : 1;
  const Eigen::Index fixed = pinned + constraints.seamContinuity + 1 - firstSeamDerivative;
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
  const double seamStart = constraints.seamStartSample ? parameters.at(*constraints.seamStartSample) : space.first();
  const double seamEnd = constraints.seamEndSample ? parameters.at(*constraints.seamEndSample) : space.last();
  for (int derivative = firstSeamDerivative; derivative <= constraints.seamContinuity; ++derivative) {
    // The derivative (the point, for derivative 0) at the start minus the one at the end is zero.
    const Eigen::MatrixXd start = basisMatrix(space, {seamStart}, derivative);
    const Eigen::MatrixXd end = basisMatrix(space, {seamEnd}, derivative);
    for (Eigen::Index pole = 0; pole < poles; ++pole)
      addConstraintEntry(pinned + derivative - firstSeamDerivative, pole, start(0, pole) - end(0, pole));
  }
  Eigen::SparseMatrix<double> system(poles + fixed, poles + fixed);
  system.setFromTriplets(entries.begin(), entries.end());
  system.makeCompressed();
  factorise(system);
  if (solver_.info() != Eigen::Success)
    throw Error(ErrorCode::InvalidArgument,
                "the approximation system is singular: " + std::to_string(parameters.size()) + " samples and " +
                    std::to_string(fixed) + " constraints for " + std::to_string(poles) + " control points");
  const Eigen::MatrixXd solution = solver_.solve(rightSide);
  return solution.topRows(poles);
}

gp_Pnt rowPoint(const PoleMatrix& points, std::size_t i) {
  const auto row = static_cast<Eigen::Index>(i);
  return gp_Pnt(points(row, 0), points(row, 1), points(row, 2));
}

/// The parameter of the foot of `point` on `curve`, by Newton's method on the squared
/// distance from `start`; a step out of the curve's range returns to `start` and stops.
/// (An adaptor keeps the polynomial of the last knot span: the points come in order.)
double footParameter(const GeomAdaptor_Curve& curve, const gp_Pnt& point, double start) {
  constexpr int kMaxSteps = 10;
  constexpr double kStepTolerance = 1e-6;
  double t = start;
  for (int step = 0; step < kMaxSteps; ++step) {
    gp_Pnt at;
    gp_Vec d1, d2;
    curve.D2(t, at, d1, d2);
    const gp_Vec offset(point, at);
    const double slope = offset.Dot(d1), curvature = offset.Dot(d2) + d1.SquareMagnitude();
    double dt = -slope / curvature;
    if (!std::isfinite(dt) || t + dt < curve.FirstParameter() || t + dt > curve.LastParameter()) return start;
    t += dt;
    if (std::abs(dt) <= kStepTolerance) break;
  }
  return t;
}

double fitError(const GeomAdaptor_Curve& curve, const std::vector<double>& parameters, const PoleMatrix& points,
                FitError measure) {
  double largest = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const double d = curve.Value(parameters[i]).Distance(rowPoint(points, i));
    largest = std::max(largest, d);
    squares += d * d;
  }
  if (measure == FitError::Largest || parameters.empty()) return largest;
  return std::sqrt(squares / static_cast<double>(parameters.size()));
}

}  // namespace

PoleMatrix approximatePoles(const KnotVector& space, const std::vector<double>& parameters, const PoleMatrix& points,
                            const InterpolationConstraints& constraints) {
  return ApproximationSolver().solve(space, parameters, points, constraints);
}

Handle(Geom_BSplineCurve)
    fitCorrectingParameters(const KnotVector& space, std::vector<double> parameters, const PoleMatrix& points,
                            const InterpolationConstraints& constraints, FitError measure, int maxCorrections) {
  constexpr double kWorthwhileGain = 1e-3;
  ApproximationSolver solver;
  Handle(Geom_BSplineCurve) curve = makeCurve(space, solver.solve(space, parameters, points, constraints));
  GeomAdaptor_Curve evaluator(curve);
  double error = fitError(evaluator, parameters, points, measure), previous = 2.0 * error;
  for (int correction = 0;
       correction < maxCorrections && error > 0.0 && (previous - error) / std::max(error, 1e-6) > kWorthwhileGain;
       ++correction) {
    for (std::size_t i = 0; i < parameters.size(); ++i)
      parameters[i] = footParameter(evaluator, rowPoint(points, i), parameters[i]);
    curve = makeCurve(space, solver.solve(space, parameters, points, constraints));
    evaluator.Load(curve);
    previous = error;
    error = fitError(evaluator, parameters, points, measure);
  }
  return curve;
}

Handle(Geom_BSplineCurve)
    fitPointsCorrectingParameters(const KnotVector& space, const std::vector<double>& parameters,
                                  const std::vector<gp_Pnt>& points, const std::set<int>& pinned, FitError measure,
                                  const InterpolationConstraints& seam, int maxCorrections, SeamAt seamAt) {
  std::vector<double> sampleParameters;
  std::vector<gp_Pnt> samples, kept;
  InterpolationConstraints constraints = seam;
  constraints.parameters.clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool isPinned = pinned.count(static_cast<int>(i)) > 0;
    (isPinned ? constraints.parameters : sampleParameters).push_back(parameters[i]);
    (isPinned ? kept : samples).push_back(points[i]);
  }
  constraints.points = toMatrix(kept);
  // The list's end points stand for the curve's ends where they are samples (a pinned one
  // keeps its parameter, the range's end).
  const int last = static_cast<int>(points.size()) - 1;
  if (seamAt == SeamAt::EndPoints && !samples.empty()) {
    if (!pinned.count(0)) constraints.seamStartSample = 0;
    if (!pinned.count(last)) constraints.seamEndSample = samples.size() - 1;
  }
  return fitCorrectingParameters(space, sampleParameters, toMatrix(samples), constraints, measure, maxCorrections);
}

}  // namespace airshape::geometry
