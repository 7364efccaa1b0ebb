#include "airshape/geometry/loft_piece.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineCurve.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"

namespace airshape::geometry {

namespace {

constexpr double kFaceTolerance = 1e-7;

/// The loft's boundary curve at u over [v0, v1], as a B-spline of its own.
Handle(Geom_BSplineCurve) alongV(const Geom_BSplineSurface& loft, double u, double v0, double v1) {
  Handle(Geom_BSplineCurve) curve = Handle(Geom_BSplineCurve)::DownCast(loft.UIso(u));
  curve->Segment(v0, v1);
  return curve;
}

}  // namespace

bool isPointCurve(const Geom_BSplineCurve& curve) {
  for (int i = 2; i <= curve.NbPoles(); ++i)
    if (curve.Pole(i).Distance(curve.Pole(1)) > 1e-7) return false;
  return true;
}

TopoDS_Face loftFace(const Handle(Geom_BSplineSurface) & loft, double vStart, double vEnd) {
  double u0, u1, v0, v1;
  loft->Bounds(u0, u1, v0, v1);
  return surfacePartFace(loft, u0, u1, vStart, vEnd);
}

TopoDS_Face surfacePartFace(const Handle(Geom_BSplineSurface) & surface, double uStart, double uEnd, double vStart,
                            double vEnd) {
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  // The face gets the piece of the surface it covers, not the whole surface trimmed:
  // meshing, area integration and STEP export then only see the piece's own poles and
  // knots. Segment keeps the parameters, so points on the face keep their (u, v).
  Handle(Geom_BSplineSurface) piece = Handle(Geom_BSplineSurface)::DownCast(surface->Copy());
  if (uStart > u0 || uEnd < u1 || vStart > v0 || vEnd < v1) piece->Segment(uStart, uEnd, vStart, vEnd);
  return BRepBuilderAPI_MakeFace(piece, uStart, uEnd, vStart, vEnd, kFaceTolerance).Face();
}

TopoDS_Face loftClosingFace(const Handle(Geom_BSplineSurface) & loft, double vStart, double vEnd) {
  double u0, u1, v0, v1;
  loft->Bounds(u0, u1, v0, v1);
  return ruledFace(alongV(*loft, u0, vStart, vEnd), alongV(*loft, u1, vStart, vEnd));
}

TopoDS_Face loftCap(const Handle(Geom_BSplineSurface) & loft, double v, bool closedProfiles) {
  const auto profile = Handle(Geom_BSplineCurve)::DownCast(loft->VIso(v));
  if (isPointCurve(*profile)) return {};
  return profileCap(profile, closedProfiles);
}

TopoDS_Face profileCap(const Handle(Geom_BSplineCurve) & profile, bool closedProfile) {
  if (closedProfile) return planarFace({profile});
  return planarFace({profile, straightLine(profile->EndPoint(), profile->StartPoint())});
}

LoftPiece loftPiece(const Handle(Geom_BSplineSurface) & loft, double vStart, double vEnd, bool closedProfiles) {
  LoftPiece piece;
  piece.skin = loftFace(loft, vStart, vEnd);
  if (!closedProfiles) piece.closingFace = loftClosingFace(loft, vStart, vEnd);
  try {
    piece.startCap = loftCap(loft, vStart, closedProfiles);
    piece.endCap = loftCap(loft, vEnd, closedProfiles);
    piece.solid = sewnSolid({piece.skin, piece.closingFace, piece.startCap, piece.endCap});
  } catch (const Error& error) {
    piece.solidProblem = error.message();
  }
  return piece;
}

}  // namespace airshape::geometry
