#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>

#include "airshape/geometry/bspline_basis.h"

namespace airshape::geometry {

/// Control points as rows of an n x 3 matrix, the form the linear algebra works in.
using PoleMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3>;

PoleMatrix toMatrix(const std::vector<gp_Pnt>& points);

/// A non-rational B-spline curve with the given space and control points (rows).
Handle(Geom_BSplineCurve) makeCurve(const KnotVector& space, const PoleMatrix& poles);

/// The knot vector of an existing curve.
KnotVector knotVectorOf(const Geom_BSplineCurve& curve);

/// Control points of an existing curve as rows.
PoleMatrix polesOf(const Geom_BSplineCurve& curve);

/// Moves the curve's parameter linearly onto [first, last]; its shape does not change.
void setParameterRange(Geom_BSplineCurve& curve, double first, double last);

/// Chord-length (exponent 1) or centripetal (exponent 0.5) parameters of a point list,
/// normalised to [0, 1].
std::vector<double> chordParameters(const std::vector<gp_Pnt>& points, double exponent = 1.0);

}  // namespace airshape::geometry
