#include "outline_closing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape::controlsurfaces {

namespace {

/// The corners of an outline outside the wing: where its edges leaving the upper and the
/// lower point end, and its two corners beyond the wing (none for a panel, whose `lowerOut`
/// lies above the wing too).
struct OuterCorners {
  gp_Pnt upperOut, upperFar, lowerFar, lowerOut;
};

gp_Pnt inSpace(const BorderPlane& plane, const gp_Pnt2d& p) { return plane.at(p.X(), p.Y()); }

/// Where a ray from `from` along `direction` reaches the height v = `height` of its plane.
gp_Pnt2d reachHeight(const gp_Pnt2d& from, const gp_Vec2d& direction, double height) {
  const double along = (height - from.Y()) / direction.Y();
  return {from.X() + along * direction.X(), from.Y() + along * direction.Y()};
}

/// The outline closed on its own: `height` above and below its chord line, `reach` chords
/// along it.
OuterCorners ownCorners(const BorderOutline& outline) {
  const BorderPlane& plane = outline.plane;
  const double height = outline.height, far = outline.reach * plane.chord;
  if (outline.kind == BorderOutline::Kind::Panel)
    return {inSpace(plane, reachHeight(outline.upper, outline.upOut, height)),
            {},
            {},
            inSpace(plane, reachHeight(outline.lower, outline.downOut, height))};
  return {inSpace(plane, reachHeight(outline.upper, outline.upOut, height)), plane.at(far, height),
          plane.at(far, -height), inSpace(plane, reachHeight(outline.lower, outline.downOut, -height))};
}

/// A plane as its unit normal and its offset: the points p with normal . p = offset.
struct Level {
  gp_Vec normal;
  double offset = 0.0;
};

double heightOf(const Level& level, const gp_Pnt& p) { return level.normal.Dot(gp_Vec(p.XYZ())); }

/// Corners where planes meet at less than this determinant, and closing planes spanned by
/// directions at less than this sine, are not used.
constexpr double kLeastSteepness = 0.1;

/// The plane through two points that holds a direction, its normal turned along `side`;
/// nothing where the points lie nearly along the direction.
std::optional<Level> planeThrough(const gp_Pnt& a, const gp_Pnt& b, const gp_Vec& direction, const gp_Vec& side) {
  const gp_Vec across(a, b);
  gp_Vec normal = across.Crossed(direction);
  if (normal.Magnitude() < kLeastSteepness * across.Magnitude() * direction.Magnitude()) return std::nullopt;
  normal.Normalize();
  if (normal.Dot(side) < 0.0) normal.Reverse();
  return Level{normal, normal.Dot(gp_Vec(a.XYZ()))};
}

/// Where the border plane meets two closing planes; nothing where they meet at a glancing angle.
std::optional<gp_Pnt> planesMeet(const BorderPlane& plane, const Level& first, const Level& second) {
  const gp_Vec& n = plane.z;
  const double offset = n.Dot(gp_Vec(plane.origin.XYZ()));
  const double determinant = n.Dot(first.normal.Crossed(second.normal));
  if (std::abs(determinant) < kLeastSteepness) return std::nullopt;
  const gp_Vec sum = offset * first.normal.Crossed(second.normal) + first.offset * second.normal.Crossed(n) +
                     second.offset * n.Crossed(first.normal);
  return gp_Pnt((sum / determinant).XYZ());
}

/// Both outlines' corners with their far ends in common planes: the plane above the wing
/// through both upper edges' ends, the plane below through both lower edges' ends, each
/// holding the outlines' mean chord direction, and the plane beyond the wing normal to that
/// direction, past the farther chord end by the lesser margin either outline closes with on
/// its own (border planes all hold the component segment's upward direction, so they meet
/// beyond the wing, if at all: a far plane as far out as the larger border's could pass where
/// the smaller one's plane has crossed the other), times `share`. Nothing where that does not
/// close them well.
std::optional<std::pair<OuterCorners, OuterCorners>> commonCornersAt(const BorderOutline& first,
                                                                     const BorderOutline& second, double share) {
  if ((first.reach > 0.0) != (second.reach > 0.0)) return std::nullopt;
  const double sense = first.reach > 0.0 ? 1.0 : -1.0;
  gp_Vec along = sense * (first.plane.x + second.plane.x);
  const gp_Vec up = first.plane.y + second.plane.y;
  along -= along.Dot(up.Normalized()) * up.Normalized();
  along.Normalize();
  OuterCorners a = ownCorners(first), b = ownCorners(second);
  const std::optional<Level> above = planeThrough(a.upperOut, b.upperOut, along, up);
  const std::optional<Level> below = planeThrough(a.lowerOut, b.lowerOut, along, -up);
  if (!above || !below) return std::nullopt;

  Level beyond{along, -std::numeric_limits<double>::infinity()};
  double margin = std::numeric_limits<double>::infinity();
  for (const auto& [outline, own] : {std::pair{&first, &a}, std::pair{&second, &b}}) {
    const BorderPlane& plane = outline->plane;
    const gp_Pnt chordEnd = outline->reach > 0.0 ? plane.at(plane.chord, 0.0) : plane.origin;
    beyond.offset = std::max(beyond.offset, heightOf(beyond, chordEnd));
    margin = std::min(margin, heightOf(beyond, own->upperFar) - heightOf(beyond, chordEnd));
  }
  beyond.offset += share * margin;

  for (const auto& [outline, corners] : {std::pair{&first, &a}, std::pair{&second, &b}}) {
    const std::optional<gp_Pnt> upperFar = planesMeet(outline->plane, *above, beyond);
    const std::optional<gp_Pnt> lowerFar = planesMeet(outline->plane, *below, beyond);
    if (!upperFar || !lowerFar) return std::nullopt;
    // Still well above and below the wing there: at least half the height it closes at alone.
    const auto height = [&](const gp_Pnt& p) { return gp_Vec(outline->plane.origin, p).Dot(outline->plane.y); };
    if (height(*upperFar) < 0.5 * outline->height || height(*lowerFar) > -0.5 * outline->height) return std::nullopt;
    corners->upperFar = *upperFar;
    corners->lowerFar = *lowerFar;
  }
  // Each outline's far corners on its own side of the other's plane, as its points in the
  // wing are: else the ruled solid between them would cross itself out there.
  const auto keepsSide = [](const BorderOutline& outline, const OuterCorners& corners, const BorderPlane& other) {
    const auto side = [&](const gp_Pnt& p) { return gp_Vec(other.origin, p).Dot(other.z); };
    const double inWing = side(inSpace(outline.plane, outline.upper));
    return side(corners.upperFar) * inWing > 0.0 && side(corners.lowerFar) * inWing > 0.0;
  };
  if (!keepsSide(first, a, second.plane) || !keepsSide(second, b, first.plane)) return std::nullopt;
  return std::pair{a, b};
}

/// Both outlines' corners in common planes (commonCornersAt), the far plane brought nearer, down
/// to an eighth of its margin, where the border planes meet out there: an oblique border whose
/// chord runs inboard reaches past its neighbour within a few chords.
std::optional<std::pair<OuterCorners, OuterCorners>> commonCorners(const BorderOutline& first,
                                                                   const BorderOutline& second) {
  for (const double share : {1.0, 0.5, 0.25, 0.125})
    if (auto corners = commonCornersAt(first, second, share)) return corners;
  return std::nullopt;
}

/// Two panels' corners with their lids in one plane: the plane through three of the corners
/// above the wing, the fourth (above the second panel's back) moved along its edge into it.
/// The edges up from the panels keep their directions. Nothing where that edge runs nearly
/// along the plane or the corner would come down to less than half its height.
std::optional<std::pair<OuterCorners, OuterCorners>> commonLid(const BorderOutline& first,
                                                               const BorderOutline& second) {
  OuterCorners a = ownCorners(first), b = ownCorners(second);
  const gp_Vec normal = gp_Vec(a.upperOut, a.lowerOut).Crossed(gp_Vec(a.upperOut, b.upperOut));
  if (normal.Magnitude() < 1e-12) return std::nullopt;
  const gp_Vec lid = normal.Normalized();
  const gp_Pnt back = inSpace(second.plane, second.lower);
  const gp_Vec up = second.downOut.X() * second.plane.x + second.downOut.Y() * second.plane.y;
  const double steepness = up.Normalized().Dot(lid);
  if (std::abs(steepness) < kLeastSteepness) return std::nullopt;
  const double along = gp_Vec(back, a.upperOut).Dot(lid) / steepness;
  if (along < 0.5 * second.height) return std::nullopt;
  b.lowerOut = back.Translated(along * up.Normalized());
  return std::pair{a, b};
}

/// The outline's wire through its corners, its edges in the order the ruled solid and the
/// device made from the skins (device_from_skins.h) expect for its kind.
TopoDS_Wire wireThrough(const BorderOutline& outline, const OuterCorners& c) {
  const gp_Pnt upper = inSpace(outline.plane, outline.upper), lower = inSpace(outline.plane, outline.lower);
  BRepBuilderAPI_MakeWire wire;
  auto straight = [&](const gp_Pnt& from, const gp_Pnt& to) { wire.Add(BRepBuilderAPI_MakeEdge(from, to).Edge()); };
  switch (outline.kind) {
    case BorderOutline::Kind::Across:
      straight(c.lowerOut, c.upperOut);
      break;
    case BorderOutline::Kind::Shaped:
      wire.Add(outline.shaped);
      straight(upper, c.upperOut);
      break;
    case BorderOutline::Kind::Panel:
      straight(upper, c.upperOut);
      straight(c.upperOut, c.lowerOut);
      straight(c.lowerOut, lower);
      straight(lower, upper);
      return wire.Wire();
    case BorderOutline::Kind::Airfoil:
      return outline.airfoil;
  }
  straight(c.upperOut, c.upperFar);
  straight(c.upperFar, c.lowerFar);
  straight(c.lowerFar, c.lowerOut);
  if (outline.kind == BorderOutline::Kind::Shaped) straight(c.lowerOut, lower);
  return wire.Wire();
}

/// A straight cut lofted against a rounded edge: the cut between the skins made the outline's
/// "rounded" edge, straight, so that both wires have the same six edges, paired one to one by
/// the ruled loft (OCCT's loft finds no solid between a four- and a six-edge wire here). A
/// file may shape one border of a device and leave the other straight.
BorderOutline asShaped(const BorderOutline& across) {
  BorderOutline shaped = across;
  shaped.kind = BorderOutline::Kind::Shaped;
  shaped.shaped =
      BRepBuilderAPI_MakeEdge(inSpace(across.plane, across.lower), inSpace(across.plane, across.upper)).Edge();
  return shaped;
}

/// The outlines with a straight cut beside a rounded edge made shaped (asShaped).
std::vector<BorderOutline> withMatchingEdges(std::vector<BorderOutline> outlines) {
  const auto has = [&](BorderOutline::Kind kind) {
    return std::any_of(outlines.begin(), outlines.end(), [&](const BorderOutline& o) { return o.kind == kind; });
  };
  if (!has(BorderOutline::Kind::Shaped) || !has(BorderOutline::Kind::Across)) return outlines;
  for (BorderOutline& outline : outlines)
    if (outline.kind == BorderOutline::Kind::Across) outline = asShaped(outline);
  return outlines;
}

bool closesBeyond(const BorderOutline& outline) {
  return outline.kind == BorderOutline::Kind::Across || outline.kind == BorderOutline::Kind::Shaped;
}

}  // namespace

std::vector<TopoDS_Wire> closedOutlines(const std::vector<BorderOutline>& given) {
  const std::vector<BorderOutline> outlines = withMatchingEdges(given);
  std::vector<TopoDS_Wire> wires;
  if (outlines.size() == 2 && closesBeyond(outlines[0]) && closesBeyond(outlines[1]))
    if (const auto common = commonCorners(outlines[0], outlines[1])) {
      wires.push_back(wireThrough(outlines[0], common->first));
      wires.push_back(wireThrough(outlines[1], common->second));
      return wires;
    }
  const bool panels = outlines.size() == 2 && outlines[0].kind == BorderOutline::Kind::Panel &&
                      outlines[1].kind == BorderOutline::Kind::Panel;
  if (panels)
    if (const auto common = commonLid(outlines[0], outlines[1])) {
      wires.push_back(wireThrough(outlines[0], common->first));
      wires.push_back(wireThrough(outlines[1], common->second));
      return wires;
    }
  for (const BorderOutline& outline : outlines)
    wires.push_back(outline.kind == BorderOutline::Kind::Airfoil ? outline.airfoil
                                                                 : wireThrough(outline, ownCorners(outline)));
  return wires;
}

}  // namespace airshape::controlsurfaces
