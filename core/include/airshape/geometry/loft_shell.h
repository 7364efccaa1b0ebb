#pragma once

#include <vector>

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

namespace airshape::geometry {

/// The solid of a loft of closed profiles (closed in u) between its first and last site in v,
/// its skin one face per stretch between consecutive sites, built with the faces sharing
/// their edges from the start instead of sewing them afterwards: the profile at each site is
/// one edge of the faces on both sides (its curve the loft's iso-curve, its parameter lines
/// exact on both), each stretch carries its seam, and planar caps on the first and last
/// profile (none where a profile has shrunk to a point) use the skin's edges. `faces`
/// receives the front cap (null where none), the skin faces in order, the rear cap (or null).
/// Throws Error when a cap is not planar or the faces enclose no volume.
TopoDS_Solid closedLoftSolid(const Handle(Geom_BSplineSurface) & loft, const std::vector<double>& sites,
                             std::vector<TopoDS_Face>& faces);

/// A part [vStart, vEnd] of a surface closed in u: one skin face of a closed loft.
struct LoftStretch {
  Handle(Geom_BSplineSurface) surface;
  double vStart = 0.0, vEnd = 1.0;
};

/// The same for a loft of stretches of different surfaces (a guided body's rows of
/// patches, one per segment): consecutive stretches must meet with the same parameters (the
/// end profile of one the start profile of the next at every u, within the B-rep tolerance,
/// over the same u range), else Error, so that the caller can sew instead.
TopoDS_Solid closedLoftSolid(const std::vector<LoftStretch>& stretches, std::vector<TopoDS_Face>& faces);

}  // namespace airshape::geometry
