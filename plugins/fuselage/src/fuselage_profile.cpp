#include "fuselage_profile.h"

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/model/placement.h"

namespace airshape::fuselage {

namespace {

constexpr double kClosureShare = 0.005;
constexpr double kSamePoint = 1e-7;

FuselageProfile fromPointList(const schema::CurvePointListXYZType& list, const std::string& xpath) {
  const std::vector<double> x = model::parseVector(list.x, xpath + "/x"), y = model::parseVector(list.y, xpath + "/y"),
                            z = model::parseVector(list.z, xpath + "/z");
  if (x.size() != y.size() || x.size() != z.size())
    throw Error(ErrorCode::InvalidModel, "x, y and z have different lengths", {}, xpath);
  std::vector<gp_Pnt> points;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (points.empty() || points.back().Distance(gp_Pnt(x[i], y[i], z[i])) >= kSamePoint)
      points.emplace_back(x[i], y[i], z[i]);
  if (points.size() < 3)
    throw Error(ErrorCode::InvalidModel, "a fuselage profile needs at least three points", {}, xpath);

  double size = 0.0;
  for (const gp_Pnt& a : points)
    for (const gp_Pnt& b : points) size = std::max(size, a.Distance(b));
  FuselageProfile profile;
  profile.closed = points.front().Distance(points.back()) < kClosureShare * size;
  if (profile.closed) {
    const gp_Pnt seam((points.front().XYZ() + points.back().XYZ()) / 2.0);
    points.front() = seam;
    points.back() = seam;
  }
  const std::vector<double> parameters = geometry::chordParameters(points, 0.5);
  profile.curve = geometry::interpolateCurve(points, parameters, 3, profile.closed);
  return profile;
}

}  // namespace

FuselageProfile FuselageProfile::fromDefinition(const schema::ProfileGeometryType& definition) {
  if (definition.pointList) return fromPointList(*definition.pointList, definition.xpath + "/pointList");
  if (definition.standardProfile)
    throw Error(ErrorCode::NotImplemented, "standard fuselage profiles are not built yet", {}, definition.xpath);
  throw Error(ErrorCode::InvalidModel, "fuselage profile '" + definition.uID + "' has no pointList", {},
              definition.xpath);
}

}  // namespace airshape::fuselage
