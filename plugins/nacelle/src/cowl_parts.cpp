#include "cowl_parts.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <gp_Pnt2d.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/profile_outline.h"
#include "nacelle_cowl.h"
#include "nacelle_profile.h"

namespace airshape::nacelle {

double lengthShare(double zeta, const std::string& where) {
  if (zeta < -1.0 || zeta > 0.0)
    throw Error(ErrorCode::InvalidModel, "zeta " + std::to_string(zeta) + " is outside [-1, 0]", {}, where);
  return zeta + 1.0;
}

gp_Pnt PlacedProfile::at(double zeta) const {
  if (zeta <= 0.0) return lower->Value(parameterAtLengthShare(lower, zeta + 1.0));
  return upper->Value(parameterAtLengthShare(upper, zeta));
}

double PlacedProfile::chord() const {
  const gp_Pnt trailingEdge((at(1.0).XYZ() + at(-1.0).XYZ()) / 2.0);
  return at(0.0).Distance(trailingEdge);
}

namespace {

/// Points along a curve from one parameter to another, in the meridian plane (axial position x,
/// radius).
void addMeridianPoints(const Handle(Geom_Curve) & curve, double from, double to, std::vector<gp_Pnt2d>& points) {
  constexpr int kSamples = 64;
  for (int i = 0; i <= kSamples; ++i) {
    const gp_Pnt p = curve->Value(from + (to - from) * i / kSamples);
    points.emplace_back(p.X(), std::hypot(p.Y(), p.Z()));
  }
}

}  // namespace

bool meridianCrossesItself(const PlacedProfile& section, double startZetaBlending, double endZetaBlending,
                           const Handle(Geom_BSplineCurve) & inner) {
  const Handle(Geom_BSplineCurve)& lower = section.lower;
  const double startBlend = parameterAtLengthShare(lower, startZetaBlending + 1.0);
  const double endBlend = parameterAtLengthShare(lower, endZetaBlending + 1.0);
  std::vector<gp_Pnt2d> loop;
  addMeridianPoints(lower, lower->FirstParameter(), startBlend, loop);
  addMeridianPoints(inner, inner->FirstParameter(), inner->LastParameter(), loop);
  addMeridianPoints(lower, endBlend, lower->LastParameter(), loop);
  addMeridianPoints(section.upper, section.upper->FirstParameter(), section.upper->LastParameter(), loop);
  // A rotation curve that follows the lower side it replaces (startZeta = startZetaBlending,
  // endZeta = endZetaBlending) runs within rounding of it: only crossings deeper than a ten
  // thousandth of the chord count.
  return geometry::polygonCrossing(loop, 1e-4 * section.chord()).has_value();
}

void warnWhereTheMeridianCrosses(const Configuration& configuration, const schema::NacelleCowlType& cowl,
                                 const std::vector<PlacedProfile>& sections, const Handle(Geom_BSplineCurve) & inner) {
  const schema::RotationCurveType& rotation = *cowl.rotationCurve;
  std::string crossing;
  for (const PlacedProfile& section : sections)
    if (meridianCrossesItself(section, rotation.startZetaBlending, rotation.endZetaBlending, inner))
      crossing += (crossing.empty() ? "'" : ", '") + section.uID + "'";
  if (crossing.empty()) return;
  configuration.warnAboutGeometry(
      {Problem::Severity::Warning, rotation.xpath,
       "the cowl's blending lines, joined by name (startZetaBlending to startZeta, endZetaBlending to endZeta), "
       "make its meridian cross itself at section " +
           crossing + ": built as given, a solid that passes through itself"});
}

PlacedProfile placedProfile(const Configuration& configuration, const schema::NacelleSectionType& section) {
  const model::Transform placement = sectionTransform(section);
  const NacelleProfile profile =
      NacelleProfile::named(configuration, section.profileUID, false, section.xpath + "/profileUID");
  PlacedProfile result;
  result.lower = geometry::transformed(profile.lower(), placement);
  result.upper = geometry::transformed(profile.upper(), placement);
  if (section.transformation && section.transformation->translation) {
    result.angle = section.transformation->translation->x.value_or(0.0);
    result.radius = section.transformation->translation->z.value_or(0.0);
  }
  result.uID = section.uID;
  return result;
}

Handle(Geom_BSplineCurve) rotationPiece(const Configuration& configuration, const schema::NacelleCowlType& cowl) {
  if (!cowl.rotationCurve) throw Error(ErrorCode::InvalidModel, "the cowl has no rotation curve", {}, cowl.xpath);
  const schema::RotationCurveType& rotation = *cowl.rotationCurve;
  const std::string& where = rotation.xpath;
  const NacelleProfile curve =
      NacelleProfile::named(configuration, rotation.curveProfileUID, true, where + "/curveProfileUID");
  // The curve's coordinate runs as a lower side's: from −1 at its trailing end (the end further
  // along x) to 0 at its leading end, whichever way its points are written.
  Handle(Geom_BSplineCurve) forwards = Handle(Geom_BSplineCurve)::DownCast(curve.whole()->Copy());
  if (forwards->StartPoint().X() <= forwards->EndPoint().X()) forwards->Reverse();
  const double from = parameterAtLengthShare(forwards, lengthShare(rotation.startZeta, where + "/startZeta"));
  const double to = parameterAtLengthShare(forwards, lengthShare(rotation.endZeta, where + "/endZeta"));
  const schema::NacelleSectionType* reference = nullptr;
  for (const auto& section : cowl.sections->section)
    if (section.uID == rotation.referenceSectionUID && reference == nullptr) reference = &section;
  if (reference == nullptr)
    throw Error(ErrorCode::InvalidModel, "'" + rotation.referenceSectionUID + "' names no section of this cowl", {},
                where + "/referenceSectionUID");
  return geometry::transformed(curvePiece(forwards, from, to), sectionTransform(*reference));
}

}  // namespace airshape::nacelle
