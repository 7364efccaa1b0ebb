#include "airshape/geometry/bspline_curve.h"

#include <cmath>

#include <BSplCLib.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

PoleMatrix toMatrix(const std::vector<gp_Pnt>& points) {
  PoleMatrix matrix(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    matrix.row(static_cast<Eigen::Index>(i)) << points[i].X(), points[i].Y(), points[i].Z();
  return matrix;
}

Handle(Geom_BSplineCurve) makeCurve(const KnotVector& space, const PoleMatrix& poles) {
  TColgp_Array1OfPnt occPoles(1, static_cast<int>(poles.rows()));
  for (Eigen::Index i = 0; i < poles.rows(); ++i)
    occPoles(static_cast<int>(i) + 1) = gp_Pnt(poles(i, 0), poles(i, 1), poles(i, 2));
  return new Geom_BSplineCurve(occPoles, occKnots(space), occMultiplicities(space), space.degree, space.periodic);
}

KnotVector knotVectorOf(const Geom_BSplineCurve& curve) {
  KnotVector space;
  space.degree = curve.Degree();
  space.periodic = curve.IsPeriodic();
  for (int i = 1; i <= curve.NbKnots(); ++i) {
    space.knots.push_back(curve.Knot(i));
    space.multiplicities.push_back(curve.Multiplicity(i));
  }
  return space;
}

PoleMatrix polesOf(const Geom_BSplineCurve& curve) {
  PoleMatrix poles(curve.NbPoles(), 3);
  for (int i = 1; i <= curve.NbPoles(); ++i) {
    const gp_Pnt& p = curve.Pole(i);
    poles.row(i - 1) << p.X(), p.Y(), p.Z();
  }
  return poles;
}

void setParameterRange(Geom_BSplineCurve& curve, double first, double last) {
  TColStd_Array1OfReal knots(1, curve.NbKnots());
  curve.Knots(knots);
  BSplCLib::Reparametrize(first, last, knots);
  curve.SetKnots(knots);
}

std::vector<double> chordParameters(const std::vector<gp_Pnt>& points, double exponent) {
  std::vector<double> parameters(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i)
    parameters[i] = parameters[i - 1] + std::pow(points[i].Distance(points[i - 1]), exponent);
  const double total = parameters.back();
  if (!(total > 0.0)) throw Error(ErrorCode::InvalidArgument, "the points all coincide; no curve runs through them");
  for (double& t : parameters) t /= total;
  return parameters;
}

}  // namespace airshape::geometry
