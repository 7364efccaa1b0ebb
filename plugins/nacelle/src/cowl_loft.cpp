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
#include "airshape/geometry/coons_patches.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/geometry/curve_network.h"
#include "airshape/geometry/ruled_sections.h"
#include "airshape/named_shape.h"
#include "cowl_guides.h"
#include "cowl_parts.h"
#include "nacelle_profile.h"

namespace airshape::nacelle {

namespace {

/// Largest gap where a section's outline and a guide cross (they are built to meet exactly).
constexpr double kCrossingGap = 1e-6;
/// Degrees: sections closer than this around the engine are at one angle.
constexpr double kSameAngle = 1e-9;

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

/// A sector of a cowl: the angles (radians) from one section to the next about the x axis,
/// `sweep` negative where the angles fall that way.
struct Sector {
  double start = 0, sweep = 0;
};

/// The sector an outer row spans, from its edge at v0 to its edge at v1.
Sector sectorOf(const Handle(Geom_BSplineSurface) & row) {
  double u0, u1, v0, v1;
  row->Bounds(u0, u1, v0, v1);
  const double start = angleOf(row->Value(u0, v0)), middle = angleOf(row->Value(u0, 0.5 * (v0 + v1)));
  const double rising = std::fmod(angleOf(row->Value(u0, v1)) - start + 4.0 * M_PI, 2.0 * M_PI);
  const bool throughMiddle = std::fmod(middle - start + 4.0 * M_PI, 2.0 * M_PI) < rising;
  return {start, throughMiddle ? rising : rising - 2.0 * M_PI};
}

/// The arc of the circle about the x axis through `point` over the sector.
Handle(Geom_Curve) arcThrough(const gp_Pnt& point, const Sector& sector) {
  const gp_Ax2 axes(gp_Pnt(point.X(), 0, 0), gp_Dir(1, 0, 0), gp_Dir(0, 0, 1));
  const Handle(Geom_Circle) circle = new Geom_Circle(axes, std::hypot(point.Y(), point.Z()));
  // The circle's parameter runs from +z towards −y, as the angles do.
  const double end = sector.start + sector.sweep;
  Handle(Geom_TrimmedCurve) arc =
      new Geom_TrimmedCurve(circle, std::min(sector.start, end), std::max(sector.start, end));
  if (sector.sweep < 0) arc->Reverse();
  return arc;
}

/// The ruled face between a row's boundary at a blending zeta and the inner side's arc through
/// `innerEnd` over the same sector, both run the same way round.
TopoDS_Face blendingFace(const Handle(Geom_Curve) & boundary, const gp_Pnt& innerEnd, const Sector& sector) {
  const TopoDS_Face face = geometry::ruledFaceBetween(BRepBuilderAPI_MakeEdge(boundary).Edge(),
                                                      BRepBuilderAPI_MakeEdge(arcThrough(innerEnd, sector)).Edge());
  if (face.IsNull()) throw Error(ErrorCode::InvalidModel, "no ruled face joins the cowl's outer and inner side");
  return face;
}

/// The outer side as the reference library lofts sections with guides: one row of patches per
/// sector (from one section to the next, the last back to the first), a patch per cell between
/// two neighbouring guides, each the Coons filling of its four boundary pieces
/// (geometry/coons_patches.h). The guides run smoothly (C2) through the sections, so every
/// patch blends its sides in with 3t² − 2t³ across, as the fuselage's cells do where a guide
/// runs smoothly through a profile (docs/fuselage.md).
std::vector<Handle(Geom_BSplineSurface)> outerRows(const std::vector<Handle(Geom_BSplineCurve)>& outlines,
                                                   const std::vector<Handle(Geom_BSplineCurve)>& guides,
                                                   double crossingGap) {
  const geometry::CurveNetwork network = geometry::buildCurveNetwork(outlines, guides, crossingGap);
  const auto sections = static_cast<Eigen::Index>(network.profiles.size());
  const auto columns = static_cast<Eigen::Index>(network.guides.size());
  // The ring closes with the first section once more, one turn on along every guide.
  std::vector<Handle(Geom_BSplineCurve)> ring = network.profiles;
  ring.push_back(network.profiles.front());
  geometry::KnownCrossings crossings;
  crossings.profileParameters.resize(sections + 1, columns);
  crossings.guideParameters.resize(sections + 1, columns);
  for (Eigen::Index k = 0; k <= sections; ++k)
    for (Eigen::Index l = 0; l < columns; ++l) {
      const Handle(Geom_BSplineCurve)& guide = network.guides[static_cast<std::size_t>(l)];
      const double turn = k == sections ? guide->LastParameter() - guide->FirstParameter() : 0.0;
      crossings.profileParameters(k, l) = network.profileParameters(k % sections, l);
      crossings.guideParameters(k, l) = network.guideParameters(k % sections, l) + turn;
    }
  return geometry::buildCoonsPatchRows(ring, network.guides, crossings,
                                       [](std::size_t, std::size_t) { return geometry::PatchBlending::Rounded; });
}

/// The inner side over a sector: the rotation curve placed at the sector's start and turned
/// through it about the x axis.
TopoDS_Face innerFace(const Handle(Geom_BSplineCurve) & inner, const Sector& sector) {
  Handle(Geom_BSplineCurve) meridian = Handle(Geom_BSplineCurve)::DownCast(inner->Copy());
  for (int i = 1; i <= meridian->NbPoles(); ++i) {
    const gp_Pnt p = meridian->Pole(i);
    const double r = std::hypot(p.Y(), p.Z());
    meridian->SetPole(i, gp_Pnt(p.X(), -r * std::sin(sector.start), r * std::cos(sector.start)));
  }
  // Turning about +x by a positive angle takes +z towards −y, the way the angles rise.
  const gp_Dir axis = sector.sweep > 0 ? gp_Dir(1, 0, 0) : gp_Dir(-1, 0, 0);
  BRepPrimAPI_MakeRevol sweep(BRepBuilderAPI_MakeEdge(meridian).Edge(), gp_Ax1(gp_Pnt(0, 0, 0), axis),
                              std::abs(sector.sweep));
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
  // Around the engine each section must have an angle of its own (0° and 360° are one).
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const PlacedProfile &section = sections[k], &next = sections[(k + 1) % sections.size()];
    const double apart = k + 1 < sections.size() ? next.angle - section.angle : next.angle + 360.0 - section.angle;
    if (sections.size() > 1 && apart < kSameAngle)
      throw Error(ErrorCode::InvalidModel,
                  "sections '" + section.uID + "' and '" + next.uID + "' lie at the same angle around the engine (" +
                      std::to_string(section.angle) + "°, translation/x)",
                  {}, cowl.xpath + "/sections");
  }

  const double startBlend = rotation.startZetaBlending, endBlend = rotation.endZetaBlending;
  lengthShare(startBlend, rotation.xpath + "/startZetaBlending");
  lengthShare(endBlend, rotation.xpath + "/endZetaBlending");
  if (startBlend >= endBlend)
    throw Error(ErrorCode::InvalidModel, "startZetaBlending must lie behind endZetaBlending (be smaller)", {},
                rotation.xpath);

  // The outer side: patches through the sections' outlines and the guides at the outlines'
  // ends, leading edge, trailing edge(s) and the cowl's own guide zetas.
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
  std::vector<Handle(Geom_BSplineSurface)> rows;
  try {
    rows = outerRows(profiles, guides, kCrossingGap * std::max(1.0, sections.front().chord()));
  } catch (const Error& error) {
    throw Error(error.code(), "the cowl's outer surface cannot be lofted: " + error.message(), {}, cowl.xpath);
  }

  // The inner curve's ends join the blending zetas by name (schema): its start is at startZeta,
  // joined to startZetaBlending, its end at endZeta, joined to endZetaBlending.
  warnWhereTheMeridianCrosses(configuration, cowl, sections, inner);
  const gp_Pnt innerAtStartBlend = inner->StartPoint(), innerAtEndBlend = inner->EndPoint();
  // The row's boundary at u0 or u1 that lies at endZetaBlending: the one nearer the sections'
  // points there than their points at startZetaBlending.
  auto nearestSectionPoint = [&](const gp_Pnt& p, double zeta) {
    double nearest = Precision::Infinite();
    for (const PlacedProfile& section : sections) nearest = std::min(nearest, p.Distance(section.at(zeta)));
    return nearest;
  };

  // Sector by sector, so that the faces meet along the same curves and sewing only matches them.
  const std::string name = cowl.uID;
  std::vector<std::pair<std::string, TopoDS_Face>> faces;
  for (const Handle(Geom_BSplineSurface) & row : rows) {
    double u0, u1, v0, v1;
    row->Bounds(u0, u1, v0, v1);
    const Sector sector = sectorOf(row);
    const gp_Pnt atU0 = row->Value(u0, v0);
    const bool u0AtEndBlend = nearestSectionPoint(atU0, endBlend) < nearestSectionPoint(atU0, startBlend);
    faces.emplace_back(name + "/outer", BRepBuilderAPI_MakeFace(row, Precision::Confusion()).Face());
    faces.emplace_back(name + "/blending",
                       blendingFace(row->UIso(u0), u0AtEndBlend ? innerAtEndBlend : innerAtStartBlend, sector));
    faces.emplace_back(name + "/blending",
                       blendingFace(row->UIso(u1), u0AtEndBlend ? innerAtStartBlend : innerAtEndBlend, sector));
    faces.emplace_back(name + "/inner", innerFace(inner, sector));
  }
  try {
    return sewnNamedSolid(faces).shape;
  } catch (const Error& error) {
    throw Error(error.code(), "the cowl's faces do not close into a solid: " + error.message(), {}, cowl.xpath);
  }
}

}  // namespace airshape::nacelle
