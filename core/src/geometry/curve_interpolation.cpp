#include "airshape/geometry/curve_interpolation.h"

#include <algorithm>
#include <string>

#include <Eigen/SparseLU>

#include "airshape/error.h"

namespace airshape::geometry {

namespace {

void requireAscending(const std::vector<double>& parameters) {
  for (std::size_t i = 1; i < parameters.size(); ++i)
    if (!(parameters[i] > parameters[i - 1]))
      throw Error(ErrorCode::InvalidArgument,
                  "interpolation parameters must be strictly increasing (parameter " + std::to_string(i) + " is not)");
}

/// An open interpolating curve whose interior points at `kinks` are corners.
Handle(Geom_BSplineCurve) interpolateWithKinks(const std::vector<gp_Pnt>& points, const std::vector<double>& parameters,
                                               int degree, const std::vector<int>& kinks) {
  // Corners split the points into pieces; each piece is interpolated on its own and the
  // pieces are joined with a knot of multiplicity `degree` (C0) at each corner.
  std::vector<int> cuts = {0};
  for (int kink : kinks)
    if (kink > 0 && kink + 1 < static_cast<int>(points.size())) cuts.push_back(kink);
  cuts.push_back(static_cast<int>(points.size()) - 1);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  KnotVector joined;
  joined.degree = degree;
  std::vector<PoleMatrix> pieces;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const auto from = static_cast<std::size_t>(cuts[c]), to = static_cast<std::size_t>(cuts[c + 1]);
    const std::vector<gp_Pnt> piecePoints(points.begin() + static_cast<long>(from),
                                          points.begin() + static_cast<long>(to) + 1);
    const std::vector<double> pieceParameters(parameters.begin() + static_cast<long>(from),
                                              parameters.begin() + static_cast<long>(to) + 1);
    Handle(Geom_BSplineCurve) piece = interpolateCurve(piecePoints, pieceParameters, degree);
    if (piece->Degree() < degree) piece->IncreaseDegree(degree);
    const KnotVector space = knotVectorOf(*piece);
    for (std::size_t k = 0; k < space.knots.size(); ++k) {
      if (k == 0 && c > 0) {
        joined.multiplicities.back() = degree;  // the corner
        continue;
      }
      joined.knots.push_back(space.knots[k]);
      joined.multiplicities.push_back(space.multiplicities[k]);
    }
    PoleMatrix poles = polesOf(*piece);
    pieces.push_back(c == 0 ? poles : PoleMatrix(poles.bottomRows(poles.rows() - 1)));
  }
  Eigen::Index total = 0;
  for (const auto& p : pieces) total += p.rows();
  PoleMatrix poles(total, 3);
  Eigen::Index row = 0;
  for (const auto& p : pieces) {
    poles.middleRows(row, p.rows()) = p;
    row += p.rows();
  }
  return makeCurve(joined, poles);
}

}  // namespace

Eigen::MatrixXd interpolateColumns(const KnotVector& space, const std::vector<double>& parameters,
                                   const Eigen::MatrixXd& values) {
  // Banded (each row has degree + 1 non-zeros, wrapped for periodic spaces): solved sparse.
  const Eigen::SparseMatrix<double> basis = sparseBasisMatrix(space, parameters);
  if (basis.rows() != basis.cols())
    throw Error(ErrorCode::InvalidArgument, std::to_string(basis.rows()) + " points cannot determine " +
                                                std::to_string(basis.cols()) + " control points");
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(basis);
  if (solver.info() != Eigen::Success) throw Error(ErrorCode::InvalidArgument, "the interpolation system is singular");
  Eigen::MatrixXd solution = solver.solve(values);
  if (solver.info() != Eigen::Success || !solution.allFinite())
    throw Error(ErrorCode::InvalidArgument, "the interpolation system is singular");
  return solution;
}

PoleMatrix interpolatePoles(const KnotVector& space, const std::vector<double>& parameters, const PoleMatrix& points) {
  return interpolateColumns(space, parameters, points);
}

Handle(Geom_BSplineCurve) interpolateCurve(const std::vector<gp_Pnt>& points, const std::vector<double>& parameters,
                                           int degree, bool closed, const std::vector<int>& kinks) {
  if (points.size() < 2) throw Error(ErrorCode::InvalidArgument, "a curve needs at least two points");
  if (points.size() != parameters.size())
    throw Error(ErrorCode::InvalidArgument, "there must be one parameter per point");
  requireAscending(parameters);
  if (!kinks.empty() && !closed) return interpolateWithKinks(points, parameters, degree, kinks);
  if (closed) {
    if (points.front().Distance(points.back()) > 1e-10 * (1.0 + points.front().Distance(gp_Pnt(0, 0, 0))))
      throw Error(ErrorCode::InvalidArgument, "a closed curve needs its first and last points to coincide");
    const int distinct = static_cast<int>(points.size()) - 1;
    const int usable = std::min(degree, distinct - 1);
    if (usable < 1) throw Error(ErrorCode::InvalidArgument, "a closed curve needs at least two distinct points");
    const KnotVector space = periodicInterpolationKnots(parameters, usable);
    const std::vector<gp_Pnt> open(points.begin(), points.end() - 1);
    const std::vector<double> openParameters(parameters.begin(), parameters.end() - 1);
    return makeCurve(space, interpolatePoles(space, openParameters, toMatrix(open)));
  }
  const int usable = std::min(degree, static_cast<int>(points.size()) - 1);
  const KnotVector space = averagedKnots(parameters, usable);
  return makeCurve(space, interpolatePoles(space, parameters, toMatrix(points)));
}

}  // namespace airshape::geometry
