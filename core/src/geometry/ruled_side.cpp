#include "airshape/geometry/ruled_side.h"

#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/bspline_patch.h"

namespace airshape::geometry {

namespace {

/// The line parameter s of a point on the side's line at t.
double alongLine(const RuledSide& side, double t, const gp_Pnt& point) {
  const gp_Vec direction = side.lines.direction(t);
  return gp_Vec(side.lines.base(t), point).Dot(direction) / direction.SquareMagnitude();
}

/// The curve (t, s) through the crossing's points, piece after piece (a piece starts where the
/// one before ends).
Handle(Geom2d_BSplineCurve) curveOverT(const RuledSide& side, const std::vector<CrossingPiece>& pieces) {
  std::vector<gp_Pnt2d> points;
  std::vector<double> parameters;
  for (const CrossingPiece& piece : pieces)
    for (const PatchPoint& point : piece.points) {
      if (!parameters.empty() && point.t <= parameters.back() + 1e-12) continue;
      points.emplace_back(point.t, alongLine(side, point.t, point.point));
      parameters.push_back(point.t);
    }
  if (points.size() < 2) return nullptr;
  return curveThroughPoints(points, parameters);
}

/// Adds the crossing's points halfway between two where the curve over t strays from it by
/// more than the tolerance (the points were placed for the curves in the skin's parameters);
/// true when it strays nowhere, nothing where a line cannot be met.
std::optional<bool> followsCrossing(const RuledSide& side, const RuledLines& meeting, const SkinPatches& skin,
                                    std::vector<CrossingPiece>& pieces, const Handle(Geom2d_BSplineCurve) & curve,
                                    double tolerance) {
  bool follows = true;
  for (CrossingPiece& piece : pieces) {
    std::vector<PatchPoint> refined{piece.points.front()};
    for (std::size_t i = 1; i < piece.points.size(); ++i) {
      const PatchPoint &a = piece.points[i - 1], &b = piece.points[i];
      PatchPoint middle{0.5 * (a.t + b.t), 0.5 * (a.u + b.u), 0.5 * (a.v + b.v), {}};
      if (!meetLine(skin.patches[piece.patch], meeting.base(middle.t), meeting.direction(middle.t), middle))
        return std::nullopt;
      const double stray = std::abs(curve->Value(middle.t).Y() - alongLine(side, middle.t, middle.point)) *
                           side.lines.direction(middle.t).Magnitude();
      if (stray > tolerance) {
        refined.push_back(middle);
        follows = false;
      }
      refined.push_back(b);
    }
    piece.points = std::move(refined);
  }
  return follows;
}

/// The lines that meet a bound's skin: the side's own, or the rays the bound names.
RuledLines meetingLines(const RuledSide& side, const SideBound& bound) {
  if (bound.raysTowards == 0) return side.lines;
  const RuledLines& lines = side.lines;
  const double towards = bound.raysTowards > 0 ? 1.0 : -1.0;
  return {lines.base(0.0).Translated(bound.raysFrom * lines.direction(0.0)),
          lines.base(1.0).Translated(bound.raysFrom * lines.direction(1.0)), towards * lines.fromDirection,
          towards * lines.toDirection, true};
}

/// Where a bound's lines meet its skin, as the curve (t, s(t)) of the side's parameters over
/// t in [0, 1], within the tolerance of the true crossing; nothing unless every line meets
/// the skin once.
Handle(Geom2d_BSplineCurve) crossingOnSide(const RuledSide& side, const SideBound& bound, double tolerance) {
  const auto patches = skinPatches(*bound.skin);
  if (!patches) return nullptr;
  const RuledLines meeting = meetingLines(side, bound);
  std::optional<std::vector<CrossingPiece>> pieces;
  try {
    pieces = ruledCrossing(patches->patches, meeting, tolerance);
  } catch (const FoldedSkin&) {
    return nullptr;
  }
  if (!pieces || !coversAllLines(*pieces)) return nullptr;
  for (int round = 0; round < 32; ++round) {
    const Handle(Geom2d_BSplineCurve) curve = curveOverT(side, *pieces);
    if (curve.IsNull()) return nullptr;
    const std::optional<bool> follows = followsCrossing(side, meeting, *patches, *pieces, curve, tolerance);
    if (!follows) return nullptr;
    if (*follows) return curve;
  }
  return nullptr;
}

}  // namespace

RuledSide ruledSide(const gp_Pnt& a0, const gp_Pnt& b0, const gp_Pnt& a1, const gp_Pnt& b1) {
  return {{a0, a1, gp_Vec(a0, b0), gp_Vec(a1, b1)}, ruledSurface(straightLine(a0, a1), straightLine(b0, b1))};
}

std::optional<TopoDS_Face> sidePart(const RuledSide& side, const SideBound& low, const SideBound& high,
                                    double tolerance) {
  auto boundCurve = [&](const SideBound& bound) -> Handle(Geom2d_Curve) {
    if (bound.kind == SideBound::Kind::Skin) return crossingOnSide(side, bound, tolerance);
    const double s = bound.kind == SideBound::Kind::Start ? 0.0 : 1.0;
    return Handle(Geom2d_Curve)(GCE2d_MakeSegment(gp_Pnt2d(0.0, s), gp_Pnt2d(1.0, s)).Value());
  };
  const Handle(Geom2d_Curve) bottom = boundCurve(low), top = boundCurve(high);
  if (bottom.IsNull() || top.IsNull()) return std::nullopt;
  const auto at = [](const Handle(Geom2d_Curve) & curve, double t) {
    return curve->Value(curve->FirstParameter() + t * (curve->LastParameter() - curve->FirstParameter()));
  };
  // How far apart the bounds lie along the lines, sampled (a length).
  const auto gap = [&](double t) { return (at(top, t).Y() - at(bottom, t).Y()) * side.lines.direction(t).Magnitude(); };
  double widest = 0.0;
  for (int k = 0; k <= 64; ++k) {
    const double width = gap(k / 64.0);
    if (width < -tolerance) return std::nullopt;
    widest = std::max(widest, width);
  }
  if (widest <= tolerance) return TopoDS_Face();
  // Corners counterclockwise in (t, s): the part lies on the left of its boundary. An end where
  // the bounds meet has one vertex.
  const gp_Pnt2d corners2d[4] = {at(bottom, 0.0), at(bottom, 1.0), at(top, 1.0), at(top, 0.0)};
  const bool open[2] = {gap(0.0) > tolerance, gap(1.0) > tolerance};
  TopoDS_Vertex vertices[4];
  for (int k = 0; k < 4; ++k) {
    const bool meets = (k == 2 && !open[1]) || (k == 3 && !open[0]);
    vertices[k] = meets ? vertices[3 - k]
                        : vertexWithin(side.surface->Value(corners2d[k].X(), corners2d[k].Y()), 2.0 * tolerance);
  }
  auto edgeOn = [&](const Handle(Geom2d_Curve) & curve, int from, int to) {
    BRepBuilderAPI_MakeEdge edge(curve, side.surface, vertices[from], vertices[to], curve->FirstParameter(),
                                 curve->LastParameter());
    return edge.IsDone() ? edge.Edge() : TopoDS_Edge();
  };
  auto across = [&](int from, int to) {
    return edgeOn(GCE2d_MakeSegment(corners2d[from], corners2d[to]).Value(), from, to);
  };
  BRepBuilderAPI_MakeWire wire;
  const TopoDS_Edge bottomEdge = edgeOn(bottom, 0, 1), topEdge = edgeOn(top, 3, 2);
  if (bottomEdge.IsNull() || topEdge.IsNull()) return std::nullopt;
  wire.Add(bottomEdge);
  if (open[1]) wire.Add(across(1, 2));
  wire.Add(TopoDS::Edge(topEdge.Reversed()));
  if (open[0]) wire.Add(across(3, 0));
  if (!wire.IsDone()) return std::nullopt;
  BRepBuilderAPI_MakeFace face(side.surface, wire.Wire(), true);
  if (!face.IsDone()) return std::nullopt;
  TopoDS_Face made = face.Face();
  BRepLib::BuildCurves3d(made, tolerance);
  return made;
}

}  // namespace airshape::geometry
