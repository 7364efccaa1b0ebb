#include "device_from_skins.h"

#include <array>
#include <cmath>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Line.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/bspline_patch.h"
#include "airshape/geometry/ruled_crossing.h"
#include "airshape/geometry/ruled_prism.h"
#include "airshape/geometry/skin_split.h"

namespace airshape::controlsurfaces {

namespace {

using Corners = std::array<gp_Pnt, 4>;

/// The corners of a border's outline in the order its wire runs; nothing unless it is four
/// straight edges.
std::optional<Corners> cornersOf(const TopoDS_Wire& wire) {
  Corners corners;
  std::size_t count = 0;
  for (BRepTools_WireExplorer edge(wire); edge.More(); edge.Next(), ++count) {
    double first = 0.0, last = 0.0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge.Current(), first, last);
    if (count == 4 || curve.IsNull() || curve->DynamicType() != STANDARD_TYPE(Geom_Line)) return std::nullopt;
    corners[count] = BRep_Tool::Pnt(edge.CurrentVertex());
  }
  if (count != 4) return std::nullopt;
  return corners;
}

/// One side of the ruled solid between the borders: the bilinear surface whose lines run from
/// the inner outline's corner k towards its corner k + 1 at t = 0 and from the outer one's at
/// t = 1, s along them (0 at corner k, 1 at corner k + 1), as the ruled loft between the
/// outlines makes it.
struct Side {
  geometry::RuledLines lines;
  Handle(Geom_BSplineSurface) surface;
};

Side sideOf(const Corners& inner, const Corners& outer, std::size_t k) {
  const std::size_t next = (k + 1) % 4;
  Side side{{inner[k], outer[k], gp_Vec(inner[k], inner[next]), gp_Vec(outer[k], outer[next])}, nullptr};
  side.surface = geometry::ruledSurface(geometry::straightLine(inner[k], outer[k]),
                                        geometry::straightLine(inner[next], outer[next]));
  return side;
}

/// The line parameter s of a point on the side's line at t.
double alongLine(const Side& side, double t, const gp_Pnt& point) {
  const gp_Vec direction = side.lines.direction(t);
  return gp_Vec(side.lines.base(t), point).Dot(direction) / direction.SquareMagnitude();
}

/// The curve (t, s) through the crossing's points, piece after piece (a piece starts where the
/// one before ends).
Handle(Geom2d_BSplineCurve) curveOverT(const Side& side, const std::vector<geometry::CrossingPiece>& pieces) {
  std::vector<gp_Pnt2d> points;
  std::vector<double> parameters;
  for (const geometry::CrossingPiece& piece : pieces)
    for (const geometry::PatchPoint& point : piece.points) {
      if (!parameters.empty() && point.t <= parameters.back() + 1e-12) continue;
      points.emplace_back(point.t, alongLine(side, point.t, point.point));
      parameters.push_back(point.t);
    }
  if (points.size() < 2) return nullptr;
  return geometry::curveThroughPoints(points, parameters);
}

/// Adds the crossing's points halfway between two where the curve over t strays from it by
/// more than the tolerance (the points were placed for the curves in the skin's parameters);
/// true when it strays nowhere, nothing where a line cannot be met.
std::optional<bool> followsCrossing(const Side& side, const geometry::SkinPatches& skin,
                                    std::vector<geometry::CrossingPiece>& pieces,
                                    const Handle(Geom2d_BSplineCurve) & curve, double tolerance) {
  bool follows = true;
  for (geometry::CrossingPiece& piece : pieces) {
    std::vector<geometry::PatchPoint> refined{piece.points.front()};
    for (std::size_t i = 1; i < piece.points.size(); ++i) {
      const geometry::PatchPoint &a = piece.points[i - 1], &b = piece.points[i];
      geometry::PatchPoint middle{0.5 * (a.t + b.t), 0.5 * (a.u + b.u), 0.5 * (a.v + b.v), {}};
      if (!geometry::meetLine(skin.patches[piece.patch], side.lines.base(middle.t), side.lines.direction(middle.t),
                              middle))
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

/// Where a side's lines meet a skin, as the curve (t, s(t)) of the side's parameters over
/// t in [0, 1], within the tolerance of the true crossing; nothing unless every line meets
/// the skin once.
Handle(Geom2d_BSplineCurve) crossingOnSide(const TopoDS_Shape& skin, const Side& side, double tolerance) {
  const auto patches = geometry::skinPatches(skin);
  if (!patches) return nullptr;
  std::optional<std::vector<geometry::CrossingPiece>> pieces;
  try {
    pieces = geometry::ruledCrossing(patches->patches, side.lines, tolerance);
  } catch (const geometry::FoldedSkin&) {
    return nullptr;
  }
  if (!pieces || !geometry::coversAllLines(*pieces)) return nullptr;
  for (int round = 0; round < 32; ++round) {
    const Handle(Geom2d_BSplineCurve) curve = curveOverT(side, *pieces);
    if (curve.IsNull()) return nullptr;
    const std::optional<bool> follows = followsCrossing(side, *patches, *pieces, curve, tolerance);
    if (!follows) return nullptr;
    if (*follows) return curve;
  }
  return nullptr;
}

/// What bounds a side's part inside the wing along its lines: one end of the lines (s = 0 or
/// 1) or where they meet a skin.
struct SideBound {
  enum class Kind { Start, End, Skin } kind;
  const TopoDS_Shape* skin = nullptr;
};

/// The part of a side between two bounds along its lines, from t = 0 to 1, as a face of its
/// bilinear surface; null where a bound cannot be drawn.
TopoDS_Face sidePart(const Side& side, const SideBound& low, const SideBound& high, double tolerance) {
  auto boundCurve = [&](const SideBound& bound) -> Handle(Geom2d_Curve) {
    if (bound.kind == SideBound::Kind::Skin) return crossingOnSide(*bound.skin, side, tolerance);
    const double s = bound.kind == SideBound::Kind::Start ? 0.0 : 1.0;
    return Handle(Geom2d_Curve)(GCE2d_MakeSegment(gp_Pnt2d(0.0, s), gp_Pnt2d(1.0, s)).Value());
  };
  const Handle(Geom2d_Curve) bottom = boundCurve(low), top = boundCurve(high);
  if (bottom.IsNull() || top.IsNull()) return {};
  // Corners counterclockwise in (t, s): the part lies on the left of its boundary.
  const gp_Pnt2d corners2d[4] = {bottom->Value(bottom->FirstParameter()), bottom->Value(bottom->LastParameter()),
                                 top->Value(top->LastParameter()), top->Value(top->FirstParameter())};
  for (int end = 0; end < 2; ++end)
    if (corners2d[3 - end].Y() - corners2d[end].Y() <= 1e-9) return {};  // the bounds touch or cross
  TopoDS_Vertex vertices[4];
  for (int k = 0; k < 4; ++k)
    vertices[k] = geometry::vertexWithin(side.surface->Value(corners2d[k].X(), corners2d[k].Y()), tolerance);
  auto edgeOn = [&](const Handle(Geom2d_Curve) & curve, int from, int to, double first, double last) {
    BRepBuilderAPI_MakeEdge edge(curve, side.surface, vertices[from], vertices[to], first, last);
    return edge.IsDone() ? edge.Edge() : TopoDS_Edge();
  };
  const TopoDS_Edge edges[4] = {
      edgeOn(bottom, 0, 1, bottom->FirstParameter(), bottom->LastParameter()),
      edgeOn(GCE2d_MakeSegment(corners2d[1], corners2d[2]).Value(), 1, 2, 0.0, corners2d[1].Distance(corners2d[2])),
      edgeOn(top, 3, 2, top->FirstParameter(), top->LastParameter()),
      edgeOn(GCE2d_MakeSegment(corners2d[3], corners2d[0]).Value(), 3, 0, 0.0, corners2d[3].Distance(corners2d[0]))};
  BRepBuilderAPI_MakeWire wire;
  for (int k = 0; k < 4; ++k) {
    if (edges[k].IsNull()) return {};
    wire.Add(k == 2 ? TopoDS::Edge(edges[k].Reversed()) : edges[k]);
  }
  if (!wire.IsDone()) return {};
  BRepBuilderAPI_MakeFace face(side.surface, wire.Wire(), true);
  if (!face.IsDone()) return {};
  TopoDS_Face made = face.Face();
  BRepLib::BuildCurves3d(made, tolerance);
  return made;
}

/// The loop of the solid's sides around the device as seen across a skin: the lines through
/// corners 0 and 3 of each outline towards corners 1 and 2, which cross the upper and the
/// lower skin (a cut from below the wing to above it, far ends beyond the wing, a panel's front
/// and back), joined by the border planes and the solid's sides between them.
geometry::RuledLoop acrossSkins(const Corners& inner, const Corners& outer) {
  return {
      {inner[0], outer[0], outer[3], inner[3]},
      {gp_Vec(inner[0], inner[1]), gp_Vec(outer[0], outer[1]), gp_Vec(outer[3], outer[2]), gp_Vec(inner[3], inner[2])},
      false};
}

/// The loop around a trailing-edge device's part of the blunt trailing edge: lines along each
/// border's chord above and below the wing (corners 1 and 0 of the cut: above, below), which
/// sweep the border planes across the trailing edge.
geometry::RuledLoop acrossTrailingEdge(const Corners& inner, const Corners& outer) {
  const gp_Vec innerChord(inner[0], inner[3]), outerChord(outer[0], outer[3]);
  return {{inner[1], outer[1], outer[0], inner[0]}, {innerChord, outerChord, outerChord, innerChord}, false};
}

/// The pieces of a skin inside a loop's prism; nothing where the split does not apply or a
/// piece cannot be placed.
std::optional<std::vector<TopoDS_Face>> piecesInside(const TopoDS_Shape& skin, const geometry::RuledLoop& loop,
                                                     double tolerance) {
  const geometry::RuledPrism prism(loop.points, loop.directions, 10.0);
  bool undecided = false;
  const auto keep = [&](const gp_Pnt& point) {
    const std::optional<bool> inside = prism.contains(point);
    undecided = undecided || !inside;
    return inside.value_or(false);
  };
  auto pieces = geometry::skinPiecesWhere(skin, loop, keep, tolerance);
  if (undecided) return std::nullopt;
  return pieces;
}

/// The plane faces that close the sewn faces' open loops (one in each border plane), named by
/// the plane they lie in; nothing unless there are exactly two such loops.
std::optional<std::vector<std::pair<std::string, TopoDS_Face>>> bordersClosing(const TopoDS_Shape& sewn,
                                                                               const std::array<gp_Pln, 2>& planes,
                                                                               const std::array<std::string, 2>& names,
                                                                               double tolerance) {
  ShapeAnalysis_FreeBounds open(sewn, tolerance, false, false);
  const TopoDS_Compound& wires = open.GetClosedWires();
  std::vector<std::pair<std::string, TopoDS_Face>> caps;
  for (TopExp_Explorer wire(wires, TopAbs_WIRE); wire.More(); wire.Next()) {
    TopExp_Explorer vertex(wire.Current(), TopAbs_VERTEX);
    if (!vertex.More()) return std::nullopt;
    const gp_Pnt point = BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current()));
    const std::size_t which = planes[0].Distance(point) <= planes[1].Distance(point) ? 0 : 1;
    BRepBuilderAPI_MakeFace cap(planes[which], TopoDS::Wire(wire.Current()), true);
    if (!cap.IsDone()) return std::nullopt;
    caps.emplace_back(names[which], cap.Face());
  }
  if (caps.size() != 2 || caps[0].first == caps[1].first) return std::nullopt;
  return caps;
}

std::optional<NamedShape> fromSkins(const WingSkins& skins, StraightOutline outline, const Corners& inner,
                                    const Corners& outer, const DeviceFaceNames& names, double tolerance) {
  std::vector<std::pair<std::string, TopoDS_Face>> faces;
  auto addPieces = [&](const TopoDS_Shape& skin, const geometry::RuledLoop& loop, const std::string& part) {
    const auto pieces = piecesInside(skin, loop, tolerance);
    if (!pieces || pieces->empty()) return false;
    for (const TopoDS_Face& piece : *pieces) faces.emplace_back(names.prefix + part, piece);
    return true;
  };
  auto addSide = [&](std::size_t k, const SideBound& low, const SideBound& high) {
    const TopoDS_Face part = sidePart(sideOf(inner, outer, k), low, high, tolerance);
    if (!part.IsNull()) faces.emplace_back(names.prefix + names.cutterFaces, part);
    return !part.IsNull();
  };
  using Kind = SideBound::Kind;
  const geometry::RuledLoop around = acrossSkins(inner, outer);
  if (!addPieces(skins.upper, around, "upper")) return std::nullopt;
  if (outline == StraightOutline::Panel) {
    // Front, back and underside of the panel: the underside lies inside the wing.
    if (!addSide(0, {Kind::Start}, {Kind::Skin, &skins.upper}) ||
        !addSide(2, {Kind::Skin, &skins.upper}, {Kind::End}) || !addSide(3, {Kind::Start}, {Kind::End}))
      return std::nullopt;
  } else {
    if (!addPieces(skins.lower, around, "lower")) return std::nullopt;
    if (!addSide(0, {Kind::Skin, &skins.lower}, {Kind::Skin, &skins.upper})) return std::nullopt;
    if (outline == StraightOutline::CutAft && !skins.trailingEdge.IsNull() &&
        !addPieces(skins.trailingEdge, acrossTrailingEdge(inner, outer), "trailing edge"))
      return std::nullopt;
  }

  BRepBuilderAPI_Sewing sewing(geometry::kJoinTolerance);
  for (const auto& entry : faces) sewing.Add(entry.second);
  sewing.Perform();
  const auto planeOf = [](const Corners& c) {
    return gp_Pln(c[0], gp_Dir(gp_Vec(c[0], c[1]).Crossed(gp_Vec(c[0], c[3]))));
  };
  const auto caps =
      bordersClosing(sewing.SewedShape(), {planeOf(inner), planeOf(outer)},
                     {names.prefix + "inner side", names.prefix + "outer side"}, geometry::kJoinTolerance);
  if (!caps) return std::nullopt;
  std::vector<std::pair<std::string, TopoDS_Face>> closed;
  for (const auto& [name, face] : faces)
    closed.emplace_back(name, sewing.IsModified(face) ? TopoDS::Face(sewing.Modified(face)) : face);
  closed.insert(closed.end(), caps->begin(), caps->end());
  return sewnNamedSolid(closed);
}

}  // namespace

std::optional<NamedShape> deviceFromSkins(const WingSkins& skins, StraightOutline outline, const TopoDS_Wire& inner,
                                          const TopoDS_Wire& outer, const DeviceFaceNames& names, double tolerance) {
  const std::optional<Corners> innerCorners = cornersOf(inner), outerCorners = cornersOf(outer);
  if (!innerCorners || !outerCorners) return std::nullopt;
  try {
    return fromSkins(skins, outline, *innerCorners, *outerCorners, names, tolerance);
  } catch (const Standard_Failure&) {
    return std::nullopt;
  } catch (const Error&) {  // the faces do not close into a solid
    return std::nullopt;
  }
}

}  // namespace airshape::controlsurfaces
