#pragma once

#include <string>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

/// A stretch of a loft surface (u along its profiles, v across them) as B-rep: the skin
/// face over [vStart, vEnd], for open profiles the face that closes them (ruled between the
/// skin's u-boundaries: a half body's symmetry plane, a blunt trailing edge), and
/// planar caps on the profiles at vStart and vEnd where they are not points.
struct LoftPiece {
  TopoDS_Face skin, closingFace, startCap, endCap;
  TopoDS_Shape solid;
  std::string solidProblem;  ///< why there is no solid, when there is none
};

/// Whether a curve has shrunk to a point (a nose or tail tip): all its poles within 1e-7.
bool isPointCurve(const Geom_BSplineCurve& curve);

/// The skin of the loft over [vStart, vEnd] as one face, the whole u range.
TopoDS_Face loftFace(const Handle(Geom_BSplineSurface) & loft, double vStart, double vEnd);

/// The part [uStart, uEnd] × [vStart, vEnd] of a surface as one face carrying only that
/// part's poles and knots (the parameters of its points stay those of the surface).
TopoDS_Face surfacePartFace(const Handle(Geom_BSplineSurface) & surface, double uStart, double uEnd, double vStart,
                            double vEnd);

/// The face closing open profiles over [vStart, vEnd]: ruled between the skin's u-boundaries.
TopoDS_Face loftClosingFace(const Handle(Geom_BSplineSurface) & loft, double vStart, double vEnd);

/// The planar cap on the loft's profile at v (with its closing edge when the profiles are
/// open); null where the profile is a point. Throws Error when the profile is not planar.
TopoDS_Face loftCap(const Handle(Geom_BSplineSurface) & loft, double v, bool closedProfiles);

/// The planar cap on a profile curve (closed, or open and closed by a straight edge from
/// its end to its start). Throws Error when the profile is not planar.
TopoDS_Face profileCap(const Handle(Geom_BSplineCurve) & profile, bool closedProfile);

/// The B-rep of the loft over [vStart, vEnd]. A failure to close it into a solid is kept
/// in solidProblem rather than thrown, so the faces can still be measured.
LoftPiece loftPiece(const Handle(Geom_BSplineSurface) & loft, double vStart, double vEnd, bool closedProfiles);

}  // namespace airshape::geometry
