#pragma once

#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

/// Volume of a solid. Faces on polynomial (non-rational) B-spline surfaces bounded by four
/// iso-lines, the skins of lofts, are integrated exactly: Gauss–Legendre per knot span with
/// enough points for the polynomial integrand (1/3)·P·(S_u × S_v). Other faces (planar
/// caps, trimmed faces) by OCCT's adaptive Gauss–Kronrod integration (relative accuracy
/// 1e-9). A null shape measures 0.
double volumeOf(const TopoDS_Shape& solid);

/// A closed solid's volume integrated roughly (two Gauss points per knot span), with the
/// sign of its orientation: positive when its faces point outwards. Far cheaper than
/// classifying points, and close enough to tell an empty solid.
double roughSignedVolumeOf(const TopoDS_Shape& solid);

/// Area of faces: rectangular B-spline patches by Gauss–Legendre per knot span (2p + 4
/// points per direction; the integrand is smooth there), other faces by OCCT's adaptive
/// integration (relative accuracy 1e-9); 0 for null.
double areaOf(const TopoDS_Shape& faces);

}  // namespace airshape::geometry
