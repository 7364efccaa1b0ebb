#include "cowl_loft.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/geometry/gordon_surface.h"
#include "airshape/geometry/ruled_sections.h"
#include "airshape/named_shape.h"
#include "cowl_guides.h"
#include "cowl_parts.h"
#include "nacelle_profile.h"

namespace airshape::nacelle {

namespace {

/// Largest gap where a section's outline and a guide cross (they are built to meet exactly).
constexpr double kCrossingGap = 1e-6;

/// The angle of a point about the x axis, as the sections' angles count it (0 at +z, 90° at −y), radians.
double angleOf(const gp_Pnt& p) { return std::atan2(-p.Y(), p.Z()); }

/// A copy of the curve whose parameters run linearly over [start, start + span].
Handle(Geom_BSplineCurve) onRange(const Handle(Geom_BSplineCurve) & curve, double start, double span) {
  Handle(Geom_BSplineCurve) moved = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  TColStd_Array1OfReal knots(1, moved->NbKnots());
  moved->Knots(knots);
  const double first = moved->FirstParameter(), scale = span / (moved->LastParameter() - first);
  for (int i = knots.Lower(); i <= knots.Upper(); ++i) knots(i) = start + (knots(i) - first) * scale;
  moved->SetKnots(knots);
  return moved;
}

/// A section's outline without the blending part, as the outer surface runs through it: from
/// endZetaBlending over the leading edge and the upper side, along a blunt trailing edge, and
/// on the lower side up to startZetaBlending.
Handle(Geom_BSplineCurve) outline(const PlacedProfile& section, double startBlend, double endBlend) {
  const Handle(Geom_BSplineCurve)& lower = section.lower;
  std::vector<Handle(Geom_BSplineCurve)> pieces{
      curvePiece(lower, parameterAtLengthShare(lower, endBlend + 1.0), lower->LastParameter()), section.upper};
  // A blunt trailing edge's line gets parameter room by its length, as little as it is.
  const gp_Pnt upperEnd = section.upper->EndPoint(), lowerStart = lower->StartPoint();
  if (upperEnd.Distance(lowerStart) > Precision::Confusion())
    pieces.push_back(onRange(geometry::straightLine(upperEnd, lowerStart), 0.0, upperEnd.Distance(lowerStart)));
  pieces.push_back(curvePiece(lower, lower->FirstParameter(), parameterAtLengthShare(lower, startBlend + 1.0)));
  double end = 0.0;
  for (auto& piece : pieces) {
    piece = onRange(piece, end, piece->LastParameter() - piece->FirstParameter());
    end = piece->LastParameter();
  }
  return geometry::concatenateCurves(pieces);
}

/// The full circle about the x axis through `point`, starting at the angle `from` (radians) and
/// running the way of rising angles, or of falling ones when `rising` is false.
Handle(Geom_Curve) circleThrough(const gp_Pnt& point, double from, bool rising) {
  const gp_Ax2 axes(gp_Pnt(point.X(), 0, 0), gp_Dir(1, 0, 0), gp_Dir(0, 0, 1));
  Handle(Geom_TrimmedCurve) circle =
      new Geom_TrimmedCurve(new Geom_Circle(axes, std::hypot(point.Y(), point.Z())), from, from + 2.0 * M_PI);
  if (!rising) circle->Reverse();
  return circle;
}

/// The ruled face between the outer surface's boundary at `u` (a closed curve around the
/// engine) and the inner side's circle through `innerEnd`, both run the same way round.
TopoDS_Face blendingFace(const Handle(Geom_BSplineSurface) & outer, double u, const gp_Pnt& innerEnd) {
  const Handle(Geom_Curve) boundary = outer->UIso(u);
  const double first = boundary->FirstParameter(), last = boundary->LastParameter();
  const double start = angleOf(boundary->Value(first));
  const double quarter = std::remainder(angleOf(boundary->Value(first + (last - first) / 4.0)) - start, 2.0 * M_PI);
  const TopoDS_Face face =
      geometry::ruledFaceBetween(BRepBuilderAPI_MakeEdge(boundary).Edge(),
                                 BRepBuilderAPI_MakeEdge(circleThrough(innerEnd, start, quarter > 0.0)).Edge());
  if (face.IsNull()) throw Error(ErrorCode::InvalidModel, "no ruled face joins the cowl's outer and inner side");
  return face;
}

/// The inner side: the rotation curve revolved once about the x axis, its seam at `angle` (radians).
TopoDS_Face innerFace(const Handle(Geom_BSplineCurve) & inner, double angle) {
  Handle(Geom_BSplineCurve) meridian = Handle(Geom_BSplineCurve)::DownCast(inner->Copy());
  for (int i = 1; i <= meridian->NbPoles(); ++i) {
    const gp_Pnt p = meridian->Pole(i);
    const double r = std::hypot(p.Y(), p.Z());
    meridian->SetPole(i, gp_Pnt(p.X(), -r * std::sin(angle), r * std::cos(angle)));
  }
  BRepPrimAPI_MakeRevol sweep(BRepBuilderAPI_MakeEdge(meridian).Edge(), gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)));
  return TopoDS::Face(sweep.Shape());
}

}  // namespace

TopoDS_Shape loftedCowl(const Configuration& configuration, const schema::NacelleCowlType& cowl) {
  const schema::RotationCurveType& rotation = *cowl.rotationCurve;
  const Handle(Geom_BSplineCurve) inner = rotationPiece(configuration, cowl);
  std::vector<PlacedProfile> sections;
  for (const auto& section : cowl.sections->section) sections.push_back(placedProfile(configuration, section));
  for (PlacedProfile& section : sections) section.angle = std::fmod(std::fmod(section.angle, 360.0) + 360.0, 360.0);
  std::sort(sections.begin(), sections.end(), [](const auto& a, const auto& b) { return a.angle < b.angle; });

  const double startBlend = rotation.startZetaBlending, endBlend = rotation.endZetaBlending;
  lengthShare(startBlend, rotation.xpath + "/startZetaBlending");
  lengthShare(endBlend, rotation.xpath + "/endZetaBlending");
  if (startBlend >= endBlend)
    throw Error(ErrorCode::InvalidModel, "startZetaBlending must lie behind endZetaBlending (be smaller)", {},
                rotation.xpath);

  // The outer surface: the Gordon surface through the sections' outlines and the guides at the
  // outline's ends, leading edge, trailing edge(s) and the cowl's own guide zetas.
  const bool blunt = sections.front().at(1.0).Distance(sections.front().at(-1.0)) > Precision::Confusion();
  std::vector<double> required{endBlend, 0.0, -1.0, startBlend};
  if (blunt) required.push_back(1.0);
  std::vector<Handle(Geom_BSplineCurve)> profiles, guides;
  for (const PlacedProfile& section : sections) profiles.push_back(outline(section, startBlend, endBlend));
  for (const CowlGuide& guide : cowlGuides(configuration, cowl, sections, required)) {
    if (guide.zeta > startBlend + 1e-9 && guide.zeta < endBlend - 1e-9)
      throw Error(ErrorCode::InvalidModel,
                  "a guide curve at zeta " + std::to_string(guide.zeta) + " lies in the blending part", {},
                  cowl.xpath + "/guideCurves");
    guides.push_back(guide.curve);
  }
  geometry::GordonTolerances tolerances;
  tolerances.crossing = kCrossingGap * std::max(1.0, sections.front().chord());
  Handle(Geom_BSplineSurface) outer;
  try {
    // Around the engine the surface is periodic: its degree across the sections at most their count − 1.
    const int degreeAround = std::min(3, static_cast<int>(sections.size()) - 1);
    outer = geometry::buildGordonSurface(profiles, guides, tolerances, nullptr, degreeAround).surface;
  } catch (const Error& error) {
    throw Error(error.code(), "the cowl's outer surface cannot be lofted: " + error.message(), {}, cowl.xpath);
  }

  // Which end of the outlines (u) is at endZetaBlending, which at startZetaBlending.
  double u0, u1, v0, v1;
  outer->Bounds(u0, u1, v0, v1);
  const gp_Pnt atEnd = sections.front().at(endBlend);
  const bool startsAtEndBlend = outer->Value(u0, v0).Distance(atEnd) < outer->Value(u1, v0).Distance(atEnd);
  const double uEndBlend = startsAtEndBlend ? u0 : u1, uStartBlend = startsAtEndBlend ? u1 : u0;
  // The inner curve's ends, each with the blending zeta it meets (the nearer one).
  gp_Pnt innerAtStartBlend = inner->StartPoint(), innerAtEndBlend = inner->EndPoint();
  const gp_Pnt outerStart = sections.front().at(startBlend);
  if (outerStart.Distance(innerAtEndBlend) < outerStart.Distance(innerAtStartBlend))
    std::swap(innerAtStartBlend, innerAtEndBlend);

  const std::string name = cowl.uID;
  std::vector<std::pair<std::string, TopoDS_Face>> faces{
      {name + "/outer", BRepBuilderAPI_MakeFace(outer, Precision::Confusion()).Face()},
      {name + "/blending", blendingFace(outer, uStartBlend, innerAtStartBlend)},
      {name + "/blending", blendingFace(outer, uEndBlend, innerAtEndBlend)},
      {name + "/inner", innerFace(inner, angleOf(outer->Value(u0, v0)))}};
  try {
    return sewnNamedSolid(faces).shape;
  } catch (const Error& error) {
    throw Error(error.code(), "the cowl's faces do not close into a solid: " + error.message(), {}, cowl.xpath);
  }
}

}  // namespace airshape::nacelle
