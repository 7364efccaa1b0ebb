#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>

namespace airshape::geometry {

/// A cubic B-spline close to `curve` over the same parameter range, on 2^k uniform knot
/// spans: at least 8, and the largest power of two not above the curve's own span count
/// (its knots together with `pointParameters`, the parameters of the points it was
/// interpolated through). Profiles refitted this way share most of their knots, so a loft
/// through many of them stays small.
///
/// Dense samples are fitted in the least-squares sense; the ends are kept exactly, corners
/// (knots of full multiplicity where the tangent turns by more than 6 degrees) stay corners,
/// and a closed curve whose ends meet tangentially stays C2 across its seam. The sample
/// parameters are then corrected by projection onto the fit and the fit repeated while
/// that helps, so the parametrisation is kept but the shape gives way very slightly.
Handle(Geom_BSplineCurve)
    refitOnUniformSpans(const Geom_BSplineCurve& curve, const std::vector<double>& pointParameters);

}  // namespace airshape::geometry
