#include "cowl_parts.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
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
  Handle(Geom_BSplineCurve) backwards = Handle(Geom_BSplineCurve)::DownCast(curve.whole()->Copy());
  backwards->Reverse();
  const double from = parameterAtLengthShare(backwards, lengthShare(rotation.startZeta, where + "/startZeta"));
  const double to = parameterAtLengthShare(backwards, lengthShare(rotation.endZeta, where + "/endZeta"));
  const schema::NacelleSectionType* reference = nullptr;
  for (const auto& section : cowl.sections->section)
    if (section.uID == rotation.referenceSectionUID && reference == nullptr) reference = &section;
  if (reference == nullptr)
    throw Error(ErrorCode::InvalidModel, "'" + rotation.referenceSectionUID + "' names no section of this cowl", {},
                where + "/referenceSectionUID");
  return geometry::transformed(curvePiece(backwards, from, to), sectionTransform(*reference));
}

}  // namespace airshape::nacelle
