#pragma once

#include <optional>
#include <vector>

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_Curve.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include "airshape/geometry/bspline_patch.h"

namespace airshape::geometry {

/// The lines of a ruled surface: the line at t in [0, 1] runs through from + t (to − from)
/// along fromDirection + t (toDirection − fromDirection), so that its points at s are
/// base(t) + s direction(t) (the ruled surface between the lines at t = 0 and t = 1).
struct RuledLines {
  gp_Pnt from, to;
  gp_Vec fromDirection, toDirection;
  /// Whether only the half-lines from the bases along their directions count (s ≥ 0): rays
  /// from inside a closed body, which meet its skin once.
  bool rays = false;

  gp_Pnt base(double t) const { return gp_Pnt(from.XYZ() + t * (to.XYZ() - from.XYZ())); }
  gp_Vec direction(double t) const { return fromDirection + t * (toDirection - fromDirection); }
};

/// The rulings of a ruled surface between two curves: the one at t in [0, 1] runs from
/// from(u) to to(u), u = u0 + t (u1 − u0), and only its points between the curves count
/// (s in [0, 1] along direction(t) = to(u) − from(u)): a ruled face's own lines.
struct RulingSegments {
  /// How far beyond its curves a ruling's crossing still counts, as a share of its length.
  static constexpr double kEndSlack = 1e-9;
  Handle(Geom_Curve) from, to;
  double u0 = 0, u1 = 1;

  gp_Pnt base(double t) const { return from->Value(u0 + t * (u1 - u0)); }
  gp_Vec direction(double t) const { return gp_Vec(base(t), to->Value(u0 + t * (u1 - u0))); }
};

/// A patch's v-curves: the one at t in [0, 1] is its curve at u = u0 + t (u1 − u0), all of it
/// counting (a guided lifting surface's face, whose curves along its span meet a body once each); or
/// with `alongU` its u-curves, at v = v0 + t (v1 − v0) (a blunt trailing edge, ruled across
/// its thickness, whose curves along the span are the ones that cross a body).
struct PatchCurves {
  Patch patch;
  bool alongU = false;

  double fixed(double t) const {
    return alongU ? patch.v0 + t * (patch.v1 - patch.v0) : patch.u0 + t * (patch.u1 - patch.u0);
  }
  gp_Pnt base(double t) const {
    return alongU ? patch.surface->Value(patch.u0, fixed(t)) : patch.surface->Value(fixed(t), patch.v0);
  }
};

/// A part of where the lines meet a skin, on one of its patches: the points (`t` the lines'
/// parameter, in order) and the curve through them in the patch's parameters by t, which
/// follows the true crossing within the tolerance.
struct CrossingPiece {
  std::size_t patch = 0;
  std::vector<PatchPoint> points;
  Handle(Geom2d_BSplineCurve) curve;
};

/// Thrown where a line meets the skin at two points (a surface folding back over itself).
struct FoldedSkin {};

/// Where the lines meet the skin's patches, piece by patch in order of t: each line met by
/// Newton's method, each change of patch found by bisection, points added until the curves
/// follow the crossing. Where the lines pass beyond the skin's edge there is no piece. Nothing
/// when a curve cannot be made to follow the crossing; throws FoldedSkin.
std::optional<std::vector<CrossingPiece>> ruledCrossing(const std::vector<Patch>& patches, const RuledLines& lines,
                                                        double tolerance);

/// The same for the rulings of a ruled face: throws FoldedSkin where a ruling meets the skin
/// at two points.
std::optional<std::vector<CrossingPiece>> ruledCrossing(const std::vector<Patch>& patches,
                                                        const RulingSegments& rulings, double tolerance);

/// The same for a patch's curves: throws FoldedSkin where a curve meets the skin at two
/// points.
std::optional<std::vector<CrossingPiece>> ruledCrossing(const std::vector<Patch>& patches, const PatchCurves& curves,
                                                        double tolerance);

/// Whether crossing pieces run without a gap from the line at t = 0 to the line at t = 1.
bool coversAllLines(const std::vector<CrossingPiece>& pieces);

/// The cubic through points of a plane (a patch's or a surface's parameters) at ascending
/// parameters, as OCCT interpolates them; null when it cannot be made.
Handle(Geom2d_BSplineCurve)
    curveThroughPoints(const std::vector<gp_Pnt2d>& points, const std::vector<double>& parameters);

/// The point moved onto a patch's bound where it lies within the tolerance of it, so that a
/// curve ending there ends on the face's edge.
PatchPoint ontoBound(const Patch& patch, PatchPoint point, double tolerance);

}  // namespace airshape::geometry
