#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape::geometry {

/// A family of parallel lines in a plane: the line at t runs through origin + t * along in the
/// direction `across`. A web's wall is such a plane: `along` from one of its positions to the
/// next, `across` the lifting surface's up direction, so each line crosses the upper and the lower skin
/// once.
struct CrossingLines {
  gp_Pnt origin;
  gp_Vec along, across;

  gp_Pnt base(double t) const { return origin.Translated(t * along); }
  gp_Vec planeNormal() const { return along.Crossed(across).Normalized(); }
  /// The t of the line through a point of the plane.
  double lineThrough(const gp_Pnt& point) const;
};

/// Where a trace along a skin ends: at the line of the family at t, at another line of the
/// plane (through a point, along a direction) where it meets the skin, or, left open, where
/// the plane leaves the skin.
struct CrossingEnd {
  enum class Kind { AtLine, AtBorder, Open };
  Kind kind = Kind::Open;
  double t = 0.0;
  gp_Pnt through;
  gp_Vec direction;

  static CrossingEnd atLine(double t) { return {Kind::AtLine, t, {}, {}}; }
  static CrossingEnd atBorder(const gp_Pnt& through, const gp_Vec& direction) {
    return {Kind::AtBorder, 0.0, through, direction};
  }
  static CrossingEnd open() { return {}; }
};

/// The curve where the plane of `lines` meets a skin, traced from line to line between two
/// ends: one B-spline piece per skin face crossed, parametrised by t, consecutive pieces
/// sharing their end points, each within `tolerance` of the true crossing. The pieces lie in
/// the plane.
struct SkinCrossing {
  /// A straight edge of the skin: its two corners.
  using StraightEdge = std::pair<gp_Pnt, gp_Pnt>;

  std::vector<Handle(Geom_BSplineCurve)> pieces;
  /// Where an open end leaves the skin across a straight edge of it (a trailing edge's line),
  /// that edge.
  std::optional<StraightEdge> startEdge, endEdge;

  gp_Pnt start() const { return pieces.front()->StartPoint(); }
  gp_Pnt end() const { return pieces.back()->EndPoint(); }
};

/// The range of the lines (their t) across which the plane crosses the skin, from its first
/// crossing to its last (in the run of faces the trace takes); nothing when the skin is not
/// what the trace takes.
std::optional<std::pair<double, double>> crossingSpan(const TopoDS_Shape& skin, const CrossingLines& lines,
                                                      double tolerance);

/// Traces the skin crossing, or gives nothing when the skin is not what the direct trace
/// handles: faces that are not untrimmed B-spline patches, a face the plane crosses other than
/// once, faces crossed with gaps between them, an end the skin does not reach, or a line the
/// skin meets tangentially. The caller then cuts by a Boolean operation. Where the plane
/// crosses the skin in runs of faces apart from each other (a closed box surface's lower and
/// upper parts), the trace takes the run that meets the lines between t = 0 and 1, if only one does.
std::optional<SkinCrossing> traceSkinCrossing(const TopoDS_Shape& skin, const CrossingLines& lines,
                                              const CrossingEnd& from, const CrossingEnd& to, double tolerance);

}  // namespace airshape::geometry
