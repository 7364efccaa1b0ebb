#include "structural_profile.h"

#include <cmath>
#include <map>

#include <gp_Vec2d.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::structure {

namespace {

constexpr double kRadiansPerDegree = M_PI / 180.0;

const schema::ProfileBasedStructuralElementType* elementNamed(const Configuration& configuration,
                                                              const std::string& uid) {
  const auto& vehicles = configuration.cpacs().vehicles;
  if (!vehicles || !vehicles->structuralElements || !vehicles->structuralElements->profileBasedStructuralElements)
    return nullptr;
  for (const auto& element :
       vehicles->structuralElements->profileBasedStructuralElements->profileBasedStructuralElement)
    if (element.uID == uid) return &element;
  return nullptr;
}

const schema::StructuralProfileType* profileNamed(const Configuration& configuration, const std::string& uid) {
  const auto& vehicles = configuration.cpacs().vehicles;
  if (!vehicles || !vehicles->profiles || !vehicles->profiles->structuralProfiles) return nullptr;
  for (const auto& profile : vehicles->profiles->structuralProfiles->structuralProfile2D)
    if (profile.uID == uid) return &profile;
  return nullptr;
}

/// A point of the profile placed by the element's 2D transformation: scaled, turned by the
/// rotation's z (degrees) and moved.
gp_Pnt2d placed(const schema::ProfileBasedStructuralElementType& element, double x, double y) {
  if (!element.transformation) return {x, y};
  const schema::Transformation2DType& transformation = *element.transformation;
  if (transformation.scaling) {
    x *= transformation.scaling->x;
    y *= transformation.scaling->y;
  }
  const double angle = transformation.rotation ? transformation.rotation->z * kRadiansPerDegree : 0.0;
  gp_Pnt2d point(std::cos(angle) * x - std::sin(angle) * y, std::sin(angle) * x + std::cos(angle) * y);
  if (transformation.translation)
    point.Translate(gp_Vec2d(transformation.translation->x, transformation.translation->y));
  return point;
}

}  // namespace

std::vector<ProfileSheet> structuralProfileSheets(const Configuration& configuration, const std::string& elementUid,
                                                  const std::string& where) {
  const schema::ProfileBasedStructuralElementType* element = elementNamed(configuration, elementUid);
  if (element == nullptr)
    throw Error(ErrorCode::InvalidModel, "structuralElementUID '" + elementUid + "' names no profile-based element", {},
                where);
  if (!element->structuralProfileUID)
    throw Error(ErrorCode::NotImplemented,
                element->standardProfileType
                    ? "a standard profile's sheets are drawn only in the schema's picture; give a structuralProfile2D"
                    : "global beam properties give no cross section to sweep",
                {}, element->xpath);
  const schema::StructuralProfileType* profile = profileNamed(configuration, *element->structuralProfileUID);
  if (profile == nullptr)
    throw Error(ErrorCode::InvalidModel,
                "structuralProfileUID '" + *element->structuralProfileUID + "' names no structuralProfile2D", {},
                element->xpath + "/structuralProfileUID");
  std::map<std::string, gp_Pnt2d> points;
  if (profile->pointList)
    for (const auto& point : profile->pointList->point)
      if (point.uID) points.emplace(*point.uID, placed(*element, point.x, point.y));
  std::vector<ProfileSheet> sheets;
  if (profile->sheetList)
    for (const auto& sheet : profile->sheetList->sheet) {
      const auto from = points.find(sheet.fromPointUID), to = points.find(sheet.toPointUID);
      if (from == points.end() || to == points.end())
        throw Error(ErrorCode::InvalidModel, "sheet '" + sheet.uID + "' names a point the profile does not have", {},
                    sheet.xpath);
      sheets.push_back({sheet.uID, from->second, to->second});
    }
  if (sheets.empty()) throw Error(ErrorCode::InvalidModel, "the profile has no sheets", {}, profile->xpath);
  return sheets;
}

}  // namespace airshape::structure
