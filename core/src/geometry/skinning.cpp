#include "airshape/geometry/skinning.h"

#include <algorithm>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/curve_interpolation.h"

namespace airshape::geometry {

namespace {

std::vector<double> withoutClosingParameter(const std::vector<double>& parameters, const KnotVector& space) {
  return space.periodic ? std::vector<double>(parameters.begin(), parameters.end() - 1) : parameters;
}

/// Interpolates a grid of points (rows: data sites, columns: other-direction index, as
/// x,y,z triples) along the rows, returning the pole rows.
Eigen::MatrixXd interpolateRows(const KnotVector& space, const std::vector<double>& parameters,
                                const Eigen::MatrixXd& values) {
  return interpolateColumns(space, withoutClosingParameter(parameters, space), values);
}

}  // namespace

std::vector<double> averagedSectionParameters(const std::vector<Handle(Geom_BSplineCurve)>& compatibleCurves) {
  const std::size_t sections = compatibleCurves.size();
  if (sections < 2) throw Error(ErrorCode::InvalidArgument, "skinning needs at least two curves");
  const int columns = compatibleCurves.front()->NbPoles();
  std::vector<double> average(sections, 0.0);
  for (int i = 1; i <= columns; ++i) {
    std::vector<gp_Pnt> column;
    for (const auto& curve : compatibleCurves) column.push_back(curve->Pole(i));
    double length = 0.0;
    for (std::size_t k = 1; k < sections; ++k) length += column[k].Distance(column[k - 1]);
    // A column that does not move (all curves share the pole) counts as evenly spaced.
    const std::vector<double> shares = length > 1e-10 ? chordParameters(column, 0.5) : std::vector<double>();
    for (std::size_t k = 0; k < sections; ++k)
      average[k] += (shares.empty() ? double(k) / double(sections - 1) : shares[k]) / columns;
  }
  return average;
}

KnotVector skinningSpace(const std::vector<double>& parameters, int degree, bool closed) {
  const int sites = static_cast<int>(parameters.size()) - (closed ? 1 : 0);
  if (sites < 2) throw Error(ErrorCode::InvalidArgument, "skinning needs at least two curves");
  if (closed) return periodicInterpolationKnots(parameters, std::min(degree, sites - 1));
  return averagedKnots(parameters, std::min(degree, sites - 1));
}

Handle(Geom_BSplineSurface)
    makeSurface(const std::vector<std::vector<gp_Pnt>>& poles, const KnotVector& uSpace, const KnotVector& vSpace) {
  const int nu = static_cast<int>(poles.size()), nv = static_cast<int>(poles.front().size());
  TColgp_Array2OfPnt grid(1, nu, 1, nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) grid(i + 1, j + 1) = poles[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return new Geom_BSplineSurface(grid, occKnots(uSpace), occKnots(vSpace), occMultiplicities(uSpace),
                                 occMultiplicities(vSpace), uSpace.degree, vSpace.degree, uSpace.periodic,
                                 vSpace.periodic);
}

Handle(Geom_BSplineSurface) skinCurves(std::vector<Handle(Geom_BSplineCurve)> curves,
                                       const std::vector<double>& parameters, const KnotVector& space) {
  makeCompatible(curves);
  const int sites = static_cast<int>(curves.size());
  const int nu = curves.front()->NbPoles();
  Eigen::MatrixXd values(sites, 3 * nu);
  for (int k = 0; k < sites; ++k)
    for (int i = 0; i < nu; ++i) {
      const gp_Pnt& p = curves[static_cast<std::size_t>(k)]->Pole(i + 1);
      values.block(k, 3 * i, 1, 3) << p.X(), p.Y(), p.Z();
    }
  const Eigen::MatrixXd vPoles = interpolateRows(space, parameters, values);
  std::vector<std::vector<gp_Pnt>> poles(static_cast<std::size_t>(nu));
  for (int i = 0; i < nu; ++i)
    for (Eigen::Index j = 0; j < vPoles.rows(); ++j)
      poles[static_cast<std::size_t>(i)].emplace_back(vPoles(j, 3 * i), vPoles(j, 3 * i + 1), vPoles(j, 3 * i + 2));
  return makeSurface(poles, knotVectorOf(*curves.front()), space);
}

Handle(Geom_BSplineSurface)
    interpolateGrid(const std::vector<std::vector<gp_Pnt>>& points, const std::vector<double>& uParameters,
                    const KnotVector& uSpace, const std::vector<double>& vParameters, const KnotVector& vSpace) {
  const int rows = static_cast<int>(points.size());             // v sites
  const int columns = static_cast<int>(points.front().size());  // u sites
  // First along u: every grid row becomes a row of u-poles.
  Eigen::MatrixXd uValues(columns, 3 * rows);
  for (int k = 0; k < rows; ++k)
    for (int l = 0; l < columns; ++l) {
      const gp_Pnt& p = points[static_cast<std::size_t>(k)][static_cast<std::size_t>(l)];
      uValues.block(l, 3 * k, 1, 3) << p.X(), p.Y(), p.Z();
    }
  const Eigen::MatrixXd uPoles = interpolateRows(uSpace, uParameters, uValues);  // nu x 3*rows
  // Then along v, for every u-pole.
  const Eigen::Index nu = uPoles.rows();
  Eigen::MatrixXd vValues(rows, 3 * nu);
  for (int k = 0; k < rows; ++k)
    for (Eigen::Index i = 0; i < nu; ++i) vValues.block(k, 3 * i, 1, 3) = uPoles.block(i, 3 * k, 1, 3);
  const Eigen::MatrixXd poles = interpolateRows(vSpace, vParameters, vValues);  // nv x 3*nu
  std::vector<std::vector<gp_Pnt>> grid(static_cast<std::size_t>(nu));
  for (Eigen::Index i = 0; i < nu; ++i)
    for (Eigen::Index j = 0; j < poles.rows(); ++j)
      grid[static_cast<std::size_t>(i)].emplace_back(poles(j, 3 * i), poles(j, 3 * i + 1), poles(j, 3 * i + 2));
  return makeSurface(grid, uSpace, vSpace);
}

Handle(Geom_BSplineSurface) swapDirections(const Geom_BSplineSurface& surface) {
  Handle(Geom_BSplineSurface) swapped = Handle(Geom_BSplineSurface)::DownCast(surface.Copy());
  swapped->ExchangeUV();
  return swapped;
}

}  // namespace airshape::geometry
