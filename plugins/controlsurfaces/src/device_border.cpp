#include "device_border.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAPI.hxx>
#include <Geom_Curve.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopoDS.hxx>
#include <gp_GTrsf.hxx>
#include <gp_Lin.hxx>
#include <gp_Pln.hxx>
#include <tuple>

#include "airshape/error.h"
#include "line_crossings.h"

namespace airshape::controlsurfaces {

namespace {

RelativeCoordinate relative(const schema::EtaIsoLineType& eta) { return {eta.eta, eta.referenceUID}; }

BorderDefinition withMissing(BorderDefinition border, const char* element) {
  border.missing = element;
  return border;
}

/// How far (in chords of the border and in heights of the wing section) the wire reaches
/// beyond the device, so that the ruled solid between two borders surely leaves the wing.
constexpr double kReach = 5.0;

/// The least height (in chords of the border) the wire closes at above and below the chord
/// line: where the border's line meets the wing on the chord line (a spoiler at a root whose
/// plane leans out through the root's cap, a cut at the trailing edge), kReach times the
/// skins' height would be none.
constexpr double kLeastHeight = 0.1;

double closingHeight(const BorderPlane& plane, double reach, double skinHeight) {
  return std::max(std::abs(reach) * skinHeight, kLeastHeight * plane.chord);
}

/// Where a line across the wing section meets a skin: the point and the skin's direction
/// there, both in the border plane's coordinates.
struct SkinCrossing {
  gp_Pnt2d point;
  gp_Vec2d tangent;
};

gp_Pnt2d inPlane(const BorderPlane& plane, const gp_Pnt& p) {
  const gp_Vec d(plane.origin, p);
  return {d.Dot(plane.x), d.Dot(plane.y)};
}

gp_Vec2d inPlane(const BorderPlane& plane, const gp_Vec& v) { return {v.Dot(plane.x), v.Dot(plane.y)}; }

/// The crossings of the line normal to the chord at `share` of it (counted from the
/// trailing-edge point) with the wing. A border in the wing's root or tip lies in its cap: the
/// line there runs within that face, which it does not cross.
std::vector<LineCrossing> crossingsAcross(const BorderPlane& plane, LineCrossings& wing, double share) {
  std::vector<LineCrossing> hits =
      wing.of(gp_Lin(plane.at((1.0 - share) * plane.chord, 0.0), gp_Dir(plane.y)), 1e-9 * plane.chord);
  hits.erase(
      std::remove_if(hits.begin(), hits.end(),
                     [&](const LineCrossing& hit) { return std::abs(hit.normal.Normalized().Dot(plane.y)) < 1e-9; }),
      hits.end());
  return hits;
}

/// The lower and the upper skin crossing of the line normal to the chord at `xsi`, a share
/// of the chord counted from the trailing-edge point (1 is the leading-edge point).
std::pair<SkinCrossing, SkinCrossing> skinCrossings(const BorderDefinition& border, const BorderPlane& plane,
                                                    LineCrossings& wing, double xsi) {
  std::vector<LineCrossing> hits = crossingsAcross(plane, wing, xsi);
  // At an end of the chord on the wing's own edge (a spoiler reaching the trailing edge, a
  // panel from the leading edge) the line touches the wing in one point or runs along a blunt
  // trailing edge: the crossings a millionth of the chord inside stand for the edge (up to a
  // ten-thousandth where the skins meet in a cusp). Where the chord runs a little off the
  // section's own (its ends at different segment etas), the line there passes beside the thin
  // nose: the end itself, on the wing's edge, is both crossings, where the skins meet.
  const bool atChordEnd = xsi <= 0.0 || xsi >= 1.0;
  for (const double inside : {1e-6, 1e-5, 1e-4})
    if (hits.size() < 2 && atChordEnd) hits = crossingsAcross(plane, wing, xsi <= 0.0 ? inside : 1.0 - inside);
  if (hits.size() < 2 && atChordEnd) {
    const gp_Pnt end = plane.at((1.0 - xsi) * plane.chord, 0.0);
    const double near = 1e-7 * plane.chord;
    if (nearestToLine(wing.shape(), gp_Lin(end, gp_Dir(plane.y)), near).Distance(end) <= 2.0 * near) {
      const SkinCrossing edge{inPlane(plane, end), gp_Vec2d(xsi >= 1.0 ? 1.0 : -1.0, 0.0)};
      return {edge, edge};
    }
  }
  if (hits.size() < 2) {
    std::ostringstream text;
    text << "the border's line across the wing at " << std::setprecision(4) << 1.0 - xsi
         << " of its chord (from its leading edge) does not cross both skins of the wing";
    throw Error(ErrorCode::InvalidModel, text.str(), {}, border.xpath);
  }
  auto crossing = [&](const LineCrossing& hit) {
    return SkinCrossing{inPlane(plane, hit.point), inPlane(plane, plane.z.Crossed(hit.normal))};
  };
  return {crossing(hits.front()), crossing(hits.back())};
}

/// A straight line across the wing from the upper to the lower skin; the device lies aft of it
/// (reach > 0) or ahead of it (reach < 0).
BorderOutline acrossOutline(const BorderPlane& plane, const gp_Pnt2d& lower, const gp_Pnt2d& upper, double reach) {
  BorderOutline outline{BorderOutline::Kind::Across, plane};
  outline.lower = lower;
  outline.upper = upper;
  outline.upOut = gp_Vec2d(lower, upper);
  outline.downOut = outline.upOut.Reversed();
  if (outline.upOut.Y() < 0) outline.upOut.Reverse();
  if (outline.downOut.Y() > 0) outline.downOut.Reverse();
  outline.reach = reach;
  outline.height = closingHeight(plane, reach, std::max(std::abs(lower.Y()), std::abs(upper.Y())));
  return outline;
}

/// Cut straight across the wing at the border's leading edge, the device aft of it. A border
/// whose leading edge is the wing's (the whole chord moves) touches the skins in one point:
/// the cut then runs along the plane's y, as high and low as a chord.
BorderOutline straightOutline(const BorderPlane& plane, LineCrossings& wing) {
  const std::vector<LineCrossing> hits = wing.of(gp_Lin(plane.origin, gp_Dir(plane.y)), 1e-9 * plane.chord);
  const bool atLeadingEdge = hits.size() < 2 || hits.front().point.Distance(hits.back().point) < 1e-7 * plane.chord;
  if (atLeadingEdge) return acrossOutline(plane, gp_Pnt2d(0.0, -plane.chord), gp_Pnt2d(0.0, plane.chord), kReach);
  return acrossOutline(plane, inPlane(plane, hits.front().point), inPlane(plane, hits.back().point), kReach);
}

/// A rounded edge from the lower skin through a middle point between the skins to the upper
/// skin, leaving the skins along them; the device lies aft of it (reach > 0, a flap's nose)
/// or ahead of it (reach < 0, a slat's hollow back).
BorderOutline shapedOutline(const BorderDefinition& border, const BorderPlane& plane, LineCrossings& wing,
                            double reach) {
  SkinCrossing lower, upper;
  if (std::abs(border.xsiUpperSkin - border.xsiLowerSkin) < 1e-10) {
    std::tie(lower, upper) = skinCrossings(border, plane, wing, border.xsiUpperSkin);
  } else {
    upper = skinCrossings(border, plane, wing, border.xsiUpperSkin).second;
    lower = skinCrossings(border, plane, wing, border.xsiLowerSkin).first;
  }
  const auto [middleLower, middleUpper] = skinCrossings(border, plane, wing, border.xsiMiddle);
  const gp_Pnt2d middle(middleLower.point.XY() * (1.0 - border.relHeight) + middleUpper.point.XY() * border.relHeight);

  // The edge runs lower -> middle -> upper; its end tangents follow the skins in that sense.
  gp_Vec2d leaveLower = lower.tangent, reachUpper = upper.tangent;
  if ((middle.X() > lower.point.X()) != (leaveLower.X() > 0)) leaveLower.Reverse();
  if ((middle.X() > upper.point.X()) != (reachUpper.X() < 0)) reachUpper.Reverse();
  Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, 3);
  points->SetValue(1, lower.point);
  points->SetValue(2, middle);
  points->SetValue(3, upper.point);
  Geom2dAPI_Interpolate interpolation(points, false, 1e-7);
  interpolation.Load(leaveLower.Normalized(), reachUpper.Normalized());
  interpolation.Perform();
  if (!interpolation.IsDone())
    throw Error(ErrorCode::InvalidModel, "the border's rounded edge cannot be drawn", {}, border.xpath);
  const gp_Pln borderPlane(gp_Ax3(plane.origin, gp_Dir(plane.z), gp_Dir(plane.x)));

  BorderOutline outline{BorderOutline::Kind::Shaped, plane};
  outline.shaped = BRepBuilderAPI_MakeEdge(GeomAPI::To3d(interpolation.Curve(), borderPlane)).Edge();
  outline.lower = lower.point;
  outline.upper = upper.point;
  // Out of the wing along the skins' normals.
  outline.upOut = gp_Vec2d(-upper.tangent.Y(), upper.tangent.X());
  outline.downOut = gp_Vec2d(-lower.tangent.Y(), lower.tangent.X());
  if (outline.upOut.Y() < 0) outline.upOut.Reverse();
  if (outline.downOut.Y() > 0) outline.downOut.Reverse();
  outline.reach = reach;
  outline.height = closingHeight(plane, reach, std::max(std::abs(lower.point.Y()), std::abs(upper.point.Y())));
  return outline;
}

/// A spoiler's section: the wing between the border's leading and trailing edge above the
/// line at relHeight between the skins, closed well above the wing.
BorderOutline panelOutline(const BorderDefinition& border, const BorderPlane& plane, LineCrossings& wing) {
  const auto [frontLower, frontUpper] = skinCrossings(border, plane, wing, 1.0);
  const auto [backLower, backUpper] = skinCrossings(border, plane, wing, 0.0);
  auto lowerSide = [&](const SkinCrossing& lower, const SkinCrossing& upper) {
    return gp_Pnt2d(lower.point.XY() * (1.0 - border.relHeight) + upper.point.XY() * border.relHeight);
  };
  BorderOutline outline{BorderOutline::Kind::Panel, plane};
  outline.upper = lowerSide(frontLower, frontUpper);
  outline.lower = lowerSide(backLower, backUpper);
  outline.upOut = outline.downOut = gp_Vec2d(0.0, 1.0);
  outline.height =
      closingHeight(plane, kReach, std::max(std::abs(frontUpper.point.Y()), std::abs(backUpper.point.Y())));
  return outline;
}

/// The border's own airfoil: x scaled to the border's chord, z by its scaling, laid into the
/// border plane (profile x along the chord, profile z along the plane's y).
BorderOutline airfoilOutline(const BorderDefinition& border, const BorderPlane& plane, const TopoDS_Wire& airfoil) {
  gp_GTrsf place;
  // Profile y (zero on an airfoil) goes along the plane normal, keeping the map regular.
  place.SetVectorialPart(gp_Mat(plane.x.X() * plane.chord, plane.z.X(), plane.y.X() * border.airfoilScaleZ,
                                plane.x.Y() * plane.chord, plane.z.Y(), plane.y.Y() * border.airfoilScaleZ,
                                plane.x.Z() * plane.chord, plane.z.Z(), plane.y.Z() * border.airfoilScaleZ));
  place.SetTranslationPart(plane.origin.XYZ());
  BorderOutline outline{BorderOutline::Kind::Airfoil, plane};
  outline.airfoil = TopoDS::Wire(BRepBuilderAPI_GTransform(airfoil, place, true).Shape());
  return outline;
}

}  // namespace

BorderOutline skinCutOutOutline(const BorderPlane& plane, LineCrossings& wing, double upperShare, double lowerShare,
                                bool aft, const std::string& xpath) {
  BorderDefinition border;
  border.xpath = xpath;
  const gp_Pnt2d upper = skinCrossings(border, plane, wing, 1.0 - upperShare).second.point;
  const gp_Pnt2d lower = skinCrossings(border, plane, wing, 1.0 - lowerShare).first.point;
  return acrossOutline(plane, lower, upper, aft ? kReach : -kReach);
}

BorderPlane::BorderPlane(const gp_Pnt& leadingEdge, const gp_Pnt& trailingEdge, const gp_Vec& up)
    : origin(leadingEdge), chord(leadingEdge.Distance(trailingEdge)) {
  if (chord < 1e-12) throw Error(ErrorCode::InvalidModel, "the border's leading and trailing edge coincide");
  x = gp_Vec(leadingEdge, trailingEdge).Normalized();
  z = x.Crossed(up.Normalized());
  if (z.Magnitude() < 1e-12) throw Error(ErrorCode::InvalidModel, "the border's chord is normal to the wing");
  z.Normalize();
  y = z.Crossed(x);
}

BorderOutline borderOutline(const BorderDefinition& border, const BorderPlane& plane, LineCrossings& wing,
                            const TopoDS_Wire& airfoil) {
  switch (border.nose) {
    case BorderDefinition::Nose::LeadingEdgeShape:
      return shapedOutline(border, plane, wing, kReach);
    case BorderDefinition::Nose::InnerShape:
      return shapedOutline(border, plane, wing, -kReach);
    case BorderDefinition::Nose::Airfoil:
      return airfoilOutline(border, plane, airfoil);
    case BorderDefinition::Nose::Panel:
      return panelOutline(border, plane, wing);
    case BorderDefinition::Nose::StraightBack:
      // The border's chord runs from xsi 0 (its leading edge) to xsiTE, the larger skin xsi.
      return skinCutOutOutline(plane, wing, border.xsiUpperSkin / border.xsiTE, border.xsiLowerSkin / border.xsiTE,
                               false, border.xpath);
    default:
      return straightOutline(plane, wing);
  }
}

namespace {

/// What every kind of border has: where it is written, its leading- and trailing-edge etas.
template <class Border>
BorderDefinition withEtas(const Border& border) {
  BorderDefinition d;
  d.xpath = border.xpath;
  if (!border.etaLE) return withMissing(d, "etaLE");
  d.etaLE = relative(*border.etaLE);
  d.etaTE = border.etaTE ? relative(*border.etaTE) : d.etaLE;
  return d;
}

/// A border that gives its own airfoil is that airfoil, whatever else it says.
template <class Border>
BorderDefinition withAirfoil(BorderDefinition d, const Border& border) {
  if (!border.airfoil) return d;
  d.nose = BorderDefinition::Nose::Airfoil;
  d.airfoilUid = border.airfoil->airfoilUID;
  d.airfoilScaleZ = border.airfoil->scalZ;
  return d;
}

}  // namespace

BorderDefinition borderOf(const schema::ControlSurfaceBorderTrailingEdgeType& border) {
  BorderDefinition d = withEtas(border);
  if (!d.missing.empty()) return d;
  if (!border.xsiLE) return withMissing(d, "xsiLE");
  d.xsiLE = border.xsiLE->xsi;
  d.xsiTE = 1.0;
  if (border.leadingEdgeShape) {
    d.nose = BorderDefinition::Nose::LeadingEdgeShape;
    d.relHeight = border.leadingEdgeShape->relHeightLE;
    d.xsiUpperSkin = border.leadingEdgeShape->xsiUpperSkin;
    d.xsiLowerSkin = border.leadingEdgeShape->xsiLowerSkin;
    d.xsiMiddle = 1.0;
  }
  return withAirfoil(d, border);
}

BorderDefinition borderOf(const schema::ControlSurfaceBorderLeadingEdgeType& border) {
  BorderDefinition d = withEtas(border);
  if (!d.missing.empty()) return d;
  d.xsiLE = 0.0;
  if (!border.xsiTE && !border.xsiTEUpper) return withMissing(d, "xsiTE");
  const double upper = border.xsiTE ? border.xsiTE->xsi : border.xsiTEUpper.value_or(0.0);
  const double lower = border.xsiTE ? border.xsiTE->xsi : border.xsiTELower.value_or(upper);
  d.xsiTE = std::max(upper, lower);
  d.xsiUpperSkin = upper;
  d.xsiLowerSkin = lower;
  d.nose = BorderDefinition::Nose::StraightBack;
  if (border.innerShape) {
    d.nose = BorderDefinition::Nose::InnerShape;
    d.relHeight = border.innerShape->relHeightTE;
    d.xsiMiddle = border.innerShape->xsiTE;
  }
  return withAirfoil(d, border);
}

BorderDefinition borderOf(const schema::ControlSurfaceBorderSpoilerType& border) {
  BorderDefinition d = withEtas(border);
  if (!d.missing.empty()) return d;
  if (!border.xsiLE) return withMissing(d, "xsiLE");
  if (!border.xsiTE) return withMissing(d, "xsiTE");
  d.xsiLE = border.xsiLE->xsi;
  d.xsiTE = border.xsiTE->xsi;
  d.nose = BorderDefinition::Nose::Panel;
  d.relHeight = border.relHeightLE.value_or(0.5);
  return withAirfoil(d, border);
}

}  // namespace airshape::controlsurfaces
