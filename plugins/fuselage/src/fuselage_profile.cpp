#include "fuselage_profile.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/uniform_refit.h"
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
  // Re-fitted on uniform knots like the reference does: the loft through all profiles then
  // needs few knots, and the numbers agree with the reference's.
  profile.curve =
      geometry::refitOnUniformSpans(*geometry::interpolateCurve(points, parameters, 3, profile.closed), parameters);
  return profile;
}

/// A closed profile given as a function of zeta, smooth between the `breaks` (zeta values
/// where it may have corners or curvature jumps): a B-spline through dense samples, with
/// corners kept at the breaks, whose parameter is zeta.
FuselageProfile sampledProfile(const std::function<gp_Pnt(double)>& at, std::vector<double> breaks) {
  constexpr int kSamplesPerPiece = 64;
  breaks.insert(breaks.begin(), 0.0);
  breaks.push_back(1.0);
  std::vector<gp_Pnt> points;
  std::vector<double> parameters;
  std::vector<int> kinks;
  for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
    if (breaks[piece + 1] - breaks[piece] < 1e-12) continue;
    if (!parameters.empty()) kinks.push_back(static_cast<int>(parameters.size()) - 1);
    for (int i = parameters.empty() ? 0 : 1; i <= kSamplesPerPiece; ++i) {
      parameters.push_back(breaks[piece] + (breaks[piece + 1] - breaks[piece]) * i / kSamplesPerPiece);
      points.push_back(at(parameters.back()));
    }
  }
  points.back() = points.front();
  return {geometry::interpolateCurve(points, parameters, 3, false, kinks), true};
}

/// The superellipse of width and height 1: the upper and lower halves have their own
/// exponents, and lowerHeightFraction sets where the widest point lies.
FuselageProfile superEllipse(const schema::SuperEllipseProfileType& shape) {
  const double z0 = shape.lowerHeightFraction - 0.5;
  auto at = [&shape, z0](double zeta) {
    const double t = 2.0 * M_PI * zeta, s = std::abs(std::sin(t));
    const bool upper = std::cos(t) >= 0.0;
    const double z =
        upper ? z0 + (0.5 - z0) * std::pow(std::max(0.0, 1.0 - std::pow(s, shape.mUpper)), 1.0 / shape.nUpper)
              : z0 - (0.5 + z0) * std::pow(std::max(0.0, 1.0 - std::pow(s, shape.mLower)), 1.0 / shape.nLower);
    return gp_Pnt(0.0, 0.5 * std::sin(t), z);
  };
  return sampledProfile(at, {0.25, 0.5, 0.75});
}

/// The rectangle of width 1 and height heightToWidthRatio with rounded corners, from the
/// top centre towards +y; zeta is the share of the length travelled (arcs by angle).
FuselageProfile rectangle(const schema::RectangleProfileType& shape) {
  const double h = shape.heightToWidthRatio / 2.0, c = std::clamp(shape.cornerRadius.value_or(0.0), 0.0, 0.4999999);
  // Pieces around the path: straight lengths and quarter arcs, in order.
  const double straightTop = 0.5 - c, side = 2.0 * (h - c), arc = M_PI * c / 2.0;
  const std::vector<double> lengths = {straightTop, arc, side, arc, 2 * straightTop, arc, side, arc, straightTop};
  double total = 0.0;
  for (double l : lengths) total += l;
  std::vector<double> breaks;
  double run = 0.0;
  for (std::size_t i = 0; i + 1 < lengths.size(); ++i) breaks.push_back((run += lengths[i]) / total);
  auto at = [=](double zeta) {
    double s = zeta * total;
    const double centres[4][2] = {{0.5 - c, h - c}, {0.5 - c, -h + c}, {-0.5 + c, -h + c}, {-0.5 + c, h - c}};
    const double startAngle[4] = {M_PI / 2, 0.0, -M_PI / 2, M_PI};
    auto onArc = [&](int corner, double along) {
      const double a = startAngle[corner] - (c > 0 ? along / c : 0.0);
      return gp_Pnt(0.0, centres[corner][0] + c * std::cos(a), centres[corner][1] + c * std::sin(a));
    };
    if (s <= straightTop) return gp_Pnt(0.0, s, h);
    if ((s -= straightTop) <= arc) return onArc(0, s);
    if ((s -= arc) <= side) return gp_Pnt(0.0, 0.5, h - c - s);
    if ((s -= side) <= arc) return onArc(1, s);
    if ((s -= arc) <= 2 * straightTop) return gp_Pnt(0.0, 0.5 - c - s, -h);
    if ((s -= 2 * straightTop) <= arc) return onArc(2, s);
    if ((s -= arc) <= side) return gp_Pnt(0.0, -0.5, -h + c + s);
    if ((s -= side) <= arc) return onArc(3, s);
    s -= arc;
    return gp_Pnt(0.0, -0.5 + c + s, h);
  };
  return sampledProfile(at, breaks);
}

}  // namespace

FuselageProfile FuselageProfile::fromDefinition(const schema::ProfileGeometryType& definition) {
  if (definition.pointList) return fromPointList(*definition.pointList, definition.xpath + "/pointList");
  if (definition.standardProfile) {
    if (definition.standardProfile->superEllipse) return superEllipse(*definition.standardProfile->superEllipse);
    if (definition.standardProfile->rectangle) return rectangle(*definition.standardProfile->rectangle);
    throw Error(ErrorCode::InvalidModel, "the standard profile is neither a rectangle nor a superellipse", {},
                definition.xpath + "/standardProfile");
  }
  throw Error(ErrorCode::InvalidModel, "fuselage profile '" + definition.uID + "' has no pointList", {},
              definition.xpath);
}

}  // namespace airshape::fuselage
