#include "device_from_skins.h"

#include <array>
#include <functional>
#include <memory>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Line.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/bspline_patch.h"
#include "airshape/geometry/ruled_crossing.h"
#include "airshape/geometry/ruled_prism.h"
#include "airshape/geometry/ruled_side.h"
#include "airshape/geometry/skin_split.h"

namespace airshape::controlsurfaces {

namespace {

/// The corners of a border's outline in the order its wire runs.
using Corners = std::vector<gp_Pnt>;

/// The corners of a border's outline; nothing unless it is four straight edges (a straight cut
/// or a panel) or six of which only the first is curved (a rounded nose or a hollow back).
std::optional<Corners> cornersOf(const TopoDS_Wire& wire) {
  Corners corners;
  std::size_t curved = 0;
  for (BRepTools_WireExplorer edge(wire); edge.More(); edge.Next()) {
    double first = 0.0, last = 0.0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge.Current(), first, last);
    if (curve.IsNull()) return std::nullopt;
    if (curve->DynamicType() != STANDARD_TYPE(Geom_Line)) {
      if (!corners.empty()) return std::nullopt;
      ++curved;
    }
    corners.push_back(BRep_Tool::Pnt(edge.CurrentVertex()));
  }
  if (!((corners.size() == 4 && curved == 0) || (corners.size() == 6 && curved == 1))) return std::nullopt;
  return corners;
}

/// Which sides of the ruled solid (by the outline's edge each starts from) cross what: for a
/// straight outline the cut (or a panel's front) crosses both skins, for a shaped one the
/// straight edges leaving the skins from the shaped edge's ends; the far side is the solid's
/// end beyond the wing. A blunt trailing edge is crossed by lines along the chord through a
/// corner above and one below the wing.
struct Layout {
  std::size_t upperSide, lowerSide, farSide;
  std::size_t above, below, chordEnd;
};

Layout layoutOf(const Corners& corners) {
  if (corners.size() == 4) return {0, 0, 2, 1, 0, 3};
  return {1, 5, 3, 2, 5, 4};
}

/// One side of the ruled solid between the borders: the bilinear surface whose lines run from
/// the inner outline's corner k towards its corner k + 1 at t = 0 and from the outer one's at
/// t = 1, s along them (0 at corner k, 1 at corner k + 1), as the ruled loft between the
/// outlines makes it.
geometry::RuledSide sideOf(const Corners& inner, const Corners& outer, std::size_t k) {
  const std::size_t next = (k + 1) % inner.size();
  return geometry::ruledSide(inner[k], inner[next], outer[k], outer[next]);
}

/// The loop of the solid's sides around the device as seen across a skin: the lines of the
/// side that crosses the skin (at each border, towards the side's next corner) and of the far
/// side, joined by the border planes and by the solid's side beyond the wing. Where the far side
/// lies off the wing (`farOffWing`), its lines are taken through its corners along the near
/// side's: the lines swept between them in the border planes then leave the skin across its
/// edge instead of grazing a rounded leading edge, as lines turning towards the far side's
/// direction would.
geometry::RuledLoop acrossSkin(const Corners& inner, const Corners& outer, std::size_t crossing, std::size_t far,
                               bool farOffWing) {
  const geometry::RuledSide near = sideOf(inner, outer, crossing), beyond = sideOf(inner, outer, far);
  gp_Vec farInner = beyond.lines.fromDirection, farOuter = beyond.lines.toDirection;
  if (farOffWing) {
    farInner = near.lines.fromDirection;
    farOuter = near.lines.toDirection;
  } else if (near.lines.fromDirection.Dot(farInner) < 0.0) {
    // Turned the way the near lines run (the same lines), so that the prism's lines have a
    // mean direction.
    farInner.Reverse();
    farOuter.Reverse();
  }
  return {{inner[crossing], outer[crossing], outer[far], inner[far]},
          {near.lines.fromDirection, near.lines.toDirection, farOuter, farInner},
          false};
}

/// The loop around a trailing-edge device's part of the blunt trailing edge: lines along each
/// border's chord through a corner above and one below the wing, which sweep the border planes
/// across the trailing edge.
geometry::RuledLoop acrossTrailingEdge(const Corners& inner, const Corners& outer, const Layout& layout) {
  const gp_Vec innerChord(inner[layout.below], inner[layout.chordEnd]),
      outerChord(outer[layout.below], outer[layout.chordEnd]);
  return {{inner[layout.above], outer[layout.above], outer[layout.below], inner[layout.below]},
          {innerChord, outerChord, outerChord, innerChord},
          false};
}

/// Where a point lies of a region: inside or not, or nothing where that cannot be told.
using InsideTest = std::function<std::optional<bool>(const gp_Pnt&)>;

/// The pieces of a skin split along a loop that lie inside a region; nothing where the split
/// does not apply or a piece cannot be placed.
std::optional<std::vector<TopoDS_Face>> piecesInside(const TopoDS_Shape& skin, const geometry::RuledLoop& loop,
                                                     const InsideTest& inside, double tolerance) {
  bool undecided = false;
  const auto keep = [&](const gp_Pnt& point) {
    const std::optional<bool> answer = inside(point);
    undecided = undecided || !answer;
    return answer.value_or(false);
  };
  auto pieces = geometry::skinPiecesWhere(skin, loop, keep, tolerance);
  if (undecided) return std::nullopt;
  return pieces;
}

/// Inside the prism that a loop's lines sweep (closed form).
InsideTest insidePrism(const geometry::RuledLoop& loop) {
  return [prism = geometry::RuledPrism(loop.points, loop.directions, 10.0)](const gp_Pnt& point) {
    return prism.contains(point);
  };
}

/// Inside a solid (OCCT's classification).
InsideTest insideSolid(const TopoDS_Shape& solid, double tolerance) {
  auto classifier = std::make_shared<BRepClass3d_SolidClassifier>(solid);
  return [classifier, tolerance](const gp_Pnt& point) -> std::optional<bool> {
    classifier->Perform(point, tolerance);
    if (classifier->State() == TopAbs_ON || classifier->State() == TopAbs_UNKNOWN) return std::nullopt;
    return classifier->State() == TopAbs_IN;
  };
}

/// A fan of rays in each border plane, from a point inside the wing on the lines of the side
/// that crosses a skin: first along that side's lines (towards the skin, `towards` +1 or -1 of
/// the side's direction), turning round the wing's leading edge until they point at a far
/// corner beyond the other skin. Rays from inside the wing meet its convex nose once each, where
/// lines swept across it would graze it. `centre` places the rays' start on the side's lines
/// (its s, the same at both borders so that the rays lie on the side's surface).
struct Fan {
  std::size_t side;
  double centre, towards;
  std::size_t farCorner;
};

geometry::RuledLoop fanAcrossSkin(const Corners& inner, const Corners& outer, const Fan& fan) {
  const geometry::RuledSide near = sideOf(inner, outer, fan.side);
  const gp_Pnt innerStart = near.lines.from.Translated(fan.centre * near.lines.fromDirection);
  const gp_Pnt outerStart = near.lines.to.Translated(fan.centre * near.lines.toDirection);
  return {{innerStart, outerStart, outerStart, innerStart},
          {fan.towards * near.lines.fromDirection, fan.towards * near.lines.toDirection,
           gp_Vec(outerStart, outer[fan.farCorner]), gp_Vec(innerStart, inner[fan.farCorner])},
          true};
}

/// The fans of a device ahead of its outlines across the upper and the lower skin: from the
/// middle of a straight cut, or from inside the wing on the straight sides leaving the shaped
/// edge's ends, half as deep as the wing is thick there.
std::pair<Fan, Fan> fansAhead(const Corners& inner, const Corners& outer) {
  if (inner.size() == 4) return {{0, 0.5, 1.0, 3}, {0, 0.5, -1.0, 2}};
  const auto share = [&](std::size_t from, std::size_t to) {
    return 0.5 * std::min(inner[0].Distance(inner[1]) / inner[from].Distance(inner[to]),
                          outer[0].Distance(outer[1]) / outer[from].Distance(outer[to]));
  };
  return {{1, -share(1, 2), 1.0, 4}, {5, 1.0 + share(5, 0), -1.0, 3}};
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

/// The point at a share of the way along a wire's first edge, in the wire's direction.
gp_Pnt alongFirstEdge(const TopoDS_Wire& wire, double share) {
  const BRepTools_WireExplorer first(wire);
  const BRepAdaptor_Curve curve(first.Current());
  const double from = curve.FirstParameter(), to = curve.LastParameter();
  return curve.Value(first.Current().Orientation() == TopAbs_REVERSED ? to - share * (to - from)
                                                                      : from + share * (to - from));
}

/// Whether the shaped side (ruled between the outlines' first edges) lies between the skins:
/// along lines up the border planes through its rulings, the upper skin lies above it and the
/// lower skin below, within the tolerance. Between the borders a ruled side may leave the wing
/// where the skins' shape differs from the outlines' (shaped edges reaching the skins far apart
/// at the two borders); the device is then cut by a Boolean operation.
bool shapedSideInside(const WingSkins& skins, const TopoDS_Wire& innerWire, const TopoDS_Wire& outerWire,
                      const Corners& inner, const Corners& outer, double tolerance) {
  const auto upperPatches = geometry::skinPatches(skins.upper), lowerPatches = geometry::skinPatches(skins.lower);
  if (!upperPatches || !lowerPatches) return false;
  const gp_Vec innerUp(inner[4], inner[3]), outerUp(outer[4], outer[3]);  // from below the wing to above it
  for (int k = 1; k < 8; ++k) {
    const geometry::RuledLines lines{alongFirstEdge(innerWire, k / 8.0), alongFirstEdge(outerWire, k / 8.0), innerUp,
                                     outerUp};
    for (const bool upper : {true, false}) {
      std::optional<std::vector<geometry::CrossingPiece>> pieces;
      try {
        pieces = geometry::ruledCrossing((upper ? upperPatches : lowerPatches)->patches, lines, tolerance);
      } catch (const geometry::FoldedSkin&) {
        return false;
      }
      if (!pieces || !geometry::coversAllLines(*pieces)) return false;
      for (const geometry::CrossingPiece& piece : *pieces)
        for (const geometry::PatchPoint& point : piece.points) {
          const double height = gp_Vec(lines.base(point.t), point.point).Dot(lines.direction(point.t).Normalized());
          if (upper ? height < -tolerance : height > tolerance) return false;
        }
    }
  }
  return true;
}

/// A straight outline's cut (its first side, corners 0 and 1) moved ahead by a tenth of its
/// distance to the far side, which runs aft: a cut at the wing's own leading edge then misses
/// the skins, whose pieces run to their own leading edge instead of grazing it.
Corners cutAheadOfWing(Corners corners) {
  const gp_Vec ahead = 0.1 * gp_Vec(corners[2], corners[1]);
  corners[0].Translate(ahead);
  corners[1].Translate(ahead);
  return corners;
}

std::optional<NamedShape> fromSkins(const WingSkins& skins, OutlineKind kind, const TopoDS_Wire& innerWire,
                                    const TopoDS_Wire& outerWire, const Corners& inner, const Corners& outer,
                                    const TopoDS_Shape& cutter, const TopoDS_Face& shapedSide,
                                    const DeviceFaceNames& names, double tolerance) {
  const Layout layout = layoutOf(inner);
  std::vector<std::pair<std::string, TopoDS_Face>> faces;
  auto addPieces = [&](const TopoDS_Shape& skin, const geometry::RuledLoop& loop, const InsideTest& inside,
                       const std::string& part) {
    const auto pieces = piecesInside(skin, loop, inside, tolerance);
    if (!pieces || pieces->empty()) return false;
    for (const TopoDS_Face& piece : *pieces) faces.emplace_back(names.prefix + part, piece);
    return true;
  };
  // Each skin split along the sides that cross it: for a device ahead of its outlines by fans
  // round the leading edge, its pieces kept by the cutter; else by the prism of the loop.
  auto addSkin = [&](const TopoDS_Shape& skin, bool upper, const std::string& part) {
    if (kind == OutlineKind::Ahead) {
      const auto [upperFan, lowerFan] = fansAhead(inner, outer);
      return !cutter.IsNull() && addPieces(skin, fanAcrossSkin(inner, outer, upper ? upperFan : lowerFan),
                                           insideSolid(cutter, tolerance), part);
    }
    const geometry::RuledLoop loop = acrossSkin(inner, outer, upper ? layout.upperSide : layout.lowerSide,
                                                layout.farSide, kind != OutlineKind::Panel);
    return addPieces(skin, loop, insidePrism(loop), part);
  };
  auto addSide = [&](std::size_t k, const geometry::SideBound& low, const geometry::SideBound& high) {
    const std::optional<TopoDS_Face> part = geometry::sidePart(sideOf(inner, outer, k), low, high, tolerance);
    if (part && !part->IsNull()) faces.emplace_back(names.prefix + names.cutterFaces, *part);
    return part.has_value();
  };
  using Bound = geometry::SideBound::Kind;
  if (!addSkin(skins.upper, true, "upper")) return std::nullopt;
  if (kind == OutlineKind::Panel) {
    // Front, back and underside of the panel: the underside lies inside the wing.
    if (inner.size() != 4 || !addSide(0, {Bound::Start}, {Bound::Skin, &skins.upper}) ||
        !addSide(2, {Bound::Skin, &skins.upper}, {Bound::End}) || !addSide(3, {Bound::Start}, {Bound::End}))
      return std::nullopt;
  } else {
    if (!addSkin(skins.lower, false, "lower")) return std::nullopt;
    if (kind == OutlineKind::WholeChord) {
      // No front: the upper and the lower skin meet at the leading edge.
    } else if (inner.size() == 4) {
      if (!addSide(0, {Bound::Skin, &skins.lower}, {Bound::Skin, &skins.upper})) return std::nullopt;
    } else {
      // The shaped side lies inside the wing, its ends on the skins at the borders; between
      // them its ruled ends may pass a little inside the skins, which the straight sides from
      // them close.
      if (shapedSide.IsNull() || !shapedSideInside(skins, innerWire, outerWire, inner, outer, tolerance) ||
          !addSide(1, {Bound::Start}, {Bound::Skin, &skins.upper}) ||
          !addSide(5, {Bound::Skin, &skins.lower}, {Bound::End}))
        return std::nullopt;
      faces.emplace_back(names.prefix + names.cutterFaces, shapedSide);
    }
    const geometry::RuledLoop aft = acrossTrailingEdge(inner, outer, layout);
    if (kind != OutlineKind::Ahead && !skins.trailingEdge.IsNull() &&
        !addPieces(skins.trailingEdge, aft, insidePrism(aft), "trailing edge"))
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
  // Turned outwards by classifying the point at infinity: integrating the volume of trimmed
  // faces of many-knotted skins would cost more than all the rest.
  NamedShape solid = sewnNamedSolid(closed, geometry::Orienting::ByClassification);
  // Checked as OCCT checks a shape: on a wing of many short segments the skins' split curves at
  // a border can leave its plane by more than their tolerance, and the cap made in that plane
  // is flawed (a thick blended wing body). The Boolean cut builds such a device instead.
  if (!BRepCheck_Analyzer(solid.shape).IsValid()) return std::nullopt;
  return solid;
}

}  // namespace

std::optional<NamedShape> deviceFromSkins(const WingSkins& skins, OutlineKind kind, const TopoDS_Wire& inner,
                                          const TopoDS_Wire& outer, const TopoDS_Shape& cutter,
                                          const TopoDS_Face& shapedSide, const DeviceFaceNames& names,
                                          double tolerance) {
  const std::optional<Corners> innerCorners = cornersOf(inner), outerCorners = cornersOf(outer);
  if (!innerCorners || !outerCorners || innerCorners->size() != outerCorners->size()) return std::nullopt;
  if (kind == OutlineKind::WholeChord && innerCorners->size() != 4) return std::nullopt;
  try {
    if (kind == OutlineKind::WholeChord)
      return fromSkins(skins, kind, inner, outer, cutAheadOfWing(*innerCorners), cutAheadOfWing(*outerCorners), cutter,
                       shapedSide, names, tolerance);
    return fromSkins(skins, kind, inner, outer, *innerCorners, *outerCorners, cutter, shapedSide, names, tolerance);
  } catch (const Standard_Failure&) {
    return std::nullopt;
  } catch (const Error&) {  // the faces do not close into a solid
    return std::nullopt;
  }
}

}  // namespace airshape::controlsurfaces
