#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>

#include "airshape/geometry/bspline_basis.h"

namespace airshape::geometry {

/// The knots used to interpolate across curves at `parameters` in the skinning direction:
/// averaged clamped knots, or periodic ones when `closed` (then the last parameter closes
/// the period and belongs to no curve). Degree is lowered to what the count allows. The
/// Gordon surface uses one space per direction for skinning and for its tensor part alike.
KnotVector skinningSpace(const std::vector<double>& parameters, int degree, bool closed);

/// Where compatible curves sit along a skin: centripetal parameters of every column of
/// corresponding control points, averaged over the columns and normalised to [0, 1]. Curves
/// that are farther apart get more parameter room, so the skin does not overshoot.
std::vector<double> averagedSectionParameters(const std::vector<Handle(Geom_BSplineCurve)>& compatibleCurves);

/// Skins compatible curves (made so first, see makeCompatible) into a surface whose
/// u-direction is the curves' and whose v-iso-curve at parameters[k] is curve k; `space`
/// comes from skinningSpace. Degree 1 gives a ruled surface.
Handle(Geom_BSplineSurface) skinCurves(std::vector<Handle(Geom_BSplineCurve)> curves,
                                       const std::vector<double>& parameters, const KnotVector& space);

/// The tensor-product surface through the grid points[k][l] at (uParameters[l],
/// vParameters[k]), interpolated in u with uSpace and in v with vSpace.
Handle(Geom_BSplineSurface)
    interpolateGrid(const std::vector<std::vector<gp_Pnt>>& points, const std::vector<double>& uParameters,
                    const KnotVector& uSpace, const std::vector<double>& vParameters, const KnotVector& vSpace);

/// A surface from a pole grid (rows: u index, each row's columns: v index) and two spaces.
Handle(Geom_BSplineSurface)
    makeSurface(const std::vector<std::vector<gp_Pnt>>& poles, const KnotVector& uSpace, const KnotVector& vSpace);

/// The same surface with u and v exchanged.
Handle(Geom_BSplineSurface) swapDirections(const Geom_BSplineSurface& surface);

}  // namespace airshape::geometry
