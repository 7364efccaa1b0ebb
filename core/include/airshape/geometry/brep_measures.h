#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir.hxx>

namespace airshape::geometry {

/// Volume of a solid. Faces on polynomial (non-rational) B-spline surfaces bounded by four
/// iso-lines, the skins of lofts, are integrated exactly: Gauss–Legendre per knot span with
/// enough points for the polynomial integrand (1/3)·P·(S_u × S_v). Planar faces (caps)
/// count their distance from the origin times their area, the area by Green's theorem
/// along their edges, per knot span (exact for polynomial edges). A solid with any other
/// face (trimmed faces) is integrated by OCCT as a whole (adaptive, relative accuracy 1e-9).
/// A null shape measures 0.
double volumeOf(const TopoDS_Shape& solid);

/// A closed solid's volume integrated roughly, with the sign of its orientation: positive
/// when its faces point outwards. Its skins are integrated on a coarse grid where the faces'
/// shares of the volume do not nearly cancel, else with two Gauss points per knot span; its
/// planar caps exactly. Far cheaper than classifying points, and close enough to tell an
/// empty solid.
double roughSignedVolumeOf(const TopoDS_Shape& solid);

/// The area a closed plane wire encloses, by Green's theorem along its edges as the wire
/// runs them: positive when it runs anticlockwise seen from the tip of `normal`, negative
/// when clockwise.
double signedAreaEnclosed(const TopoDS_Wire& wire, const gp_Dir& normal);

/// Area of faces: rectangular B-spline patches by Gauss–Legendre per knot span (2p + 4
/// points per direction; the integrand is smooth there), planar faces by Green's theorem
/// along their edges (OCCT's adaptive integration is off by 1e-4 on caps bounded by curves
/// with thousands of knots), other faces by OCCT's adaptive integration (relative accuracy
/// 1e-9); 0 for null.
double areaOf(const TopoDS_Shape& faces);

/// The volume a shape encloses: its solids', plus that of every closed shell belonging to no
/// solid (taken positive); open shells and loose faces enclose nothing.
double enclosedVolume(const TopoDS_Shape& shape);

/// The exact arc length of the edges of a shape (each edge once per occurrence).
double lengthOf(const TopoDS_Shape& edges);

}  // namespace airshape::geometry
