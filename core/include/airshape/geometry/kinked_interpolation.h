#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>

namespace airshape::geometry {

/// The cubic curve through `points` at `parameters` with corners at the points listed in
/// `kinks` (indices): each run of points between two corners is interpolated on its own
/// and the runs are joined. A closed list (first point = last point) without a corner at
/// its ends is smooth across its seam: periodic when it has no corners at all, otherwise the
/// run through the seam is interpolated as one and split there. The result is clamped over
/// [parameters.front(), parameters.back()] (periodic only for a closed list without corners).
Handle(Geom_BSplineCurve)
    interpolateWithCorners(const std::vector<gp_Pnt>& points, const std::vector<double>& parameters,
                           std::vector<int> kinks, bool closed);

/// The same curve with a new parameter: the point that had parameter from[i] gets to[i],
/// linearly in between (from and to ascending, spanning the curve's range). The shape does
/// not change. Every to[i] is a knot of the result, of full multiplicity where the map bends
/// and at least simple elsewhere, as the reference's reparametrisation leaves them (a loft
/// that spaces its sections by their poles sees the difference).
Handle(Geom_BSplineCurve)
    reparametrisePiecewiseLinearly(const Geom_BSplineCurve& curve, const std::vector<double>& from,
                                   const std::vector<double>& to);

}  // namespace airshape::geometry
