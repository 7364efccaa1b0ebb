#include "fuselage_profile.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/bspline_basis.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/chebyshev_approximation.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/geometry/kinked_interpolation.h"
#include "airshape/geometry/profile_outline.h"
#include "airshape/geometry/uniform_refit.h"
#include "airshape/model/approximation_settings.h"
#include "airshape/model/placement.h"
#include "airshape/xml/text.h"

namespace airshape::fuselage {

namespace {

constexpr double kClosureShare = 0.005;
constexpr double kSamePoint = 1e-7;
/// The degree of an approximated profile, as the reference fits it.
constexpr int kDegree = 3;

/// Indices from a CPACS list ("1;3"), 0-based as the reference reads them.
std::vector<int> indicesOf(const std::string& text, const std::string& xpath) {
  std::vector<int> indices;
  for (double value : model::parseVector(text, xpath)) indices.push_back(static_cast<int>(std::lround(value)));
  return indices;
}

/// Whether the profile carries the reference's non-standard <symmetry>half</symmetry>: its
/// points are one half, to be mirrored in y (the schema's own symmetry values are planes).
bool isMirroredHalf(const schema::ProfileGeometryType& definition) {
  if (!definition.binding) return false;
  const auto* symmetry = xml::firstChild(*definition.binding, "symmetry");
  return symmetry && xml::text(*symmetry) == "half";
}

/// The profile's points with the indices of the list they came from (repeats dropped), and
/// the warning of an outline that crosses itself within the tolerance.
std::vector<gp_Pnt> readPoints(const schema::CurvePointListXYZType& list, const std::string& xpath,
                               std::vector<int>& listIndex, Problems& warnings) {
  const std::vector<double> x = model::parseVector(list.x, xpath + "/x"), y = model::parseVector(list.y, xpath + "/y"),
                            z = model::parseVector(list.z, xpath + "/z");
  if (x.size() != y.size() || x.size() != z.size())
    throw Error(ErrorCode::InvalidModel, "x, y and z have different lengths", {}, xpath);
  std::vector<gp_Pnt> points;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (points.empty() || points.back().Distance(gp_Pnt(x[i], y[i], z[i])) >= kSamePoint) {
      points.emplace_back(x[i], y[i], z[i]);
      listIndex.push_back(static_cast<int>(i));
    }
  if (points.size() < 3)
    throw Error(ErrorCode::InvalidModel, "a fuselage profile needs at least three points", {}, xpath);
  std::vector<gp_Pnt2d> outline;  // in the profile's plane
  for (const gp_Pnt& p : points) outline.emplace_back(p.Y(), p.Z());
  if (const auto crossing = geometry::requireProfileOutline(outline, kSamePoint, listIndex, xpath))
    warnings.push_back({Problem::Severity::Warning, xpath, *crossing});
  return points;
}

/// Where in `points` the point of list index `index` is; throws naming `xpath` when none.
int pointIndexOf(int index, const std::vector<int>& listIndex, const std::string& xpath) {
  const auto found = std::find(listIndex.begin(), listIndex.end(), index);
  if (found == listIndex.end())
    throw Error(ErrorCode::InvalidModel, "index " + std::to_string(index) + " names no point of the list", {}, xpath);
  return static_cast<int>(found - listIndex.begin());
}

/// Every point's new parameter: the pinned points (index -> parameter) get theirs, the
/// others follow linearly between them, as the reference maps them.
std::vector<double> mappedLinearly(const std::vector<double>& parameters, const std::map<int, double>& pinned) {
  std::vector<double> from, to, mapped;
  for (const auto& [index, value] : pinned) {
    from.push_back(parameters[static_cast<std::size_t>(index)]);
    to.push_back(value);
  }
  for (double t : parameters) {
    const auto above = static_cast<std::size_t>(std::upper_bound(from.begin(), from.end(), t) - from.begin());
    const std::size_t piece = std::clamp<std::size_t>(above, 1, from.size() - 1);
    const double share = (t - from[piece - 1]) / (from[piece] - from[piece - 1]);
    mapped.push_back(to[piece - 1] + share * (to[piece] - to[piece - 1]));
  }
  return mapped;
}

/// The list's kinks as indices into the points read (repeats dropped). `firstIndex` is the
/// index the list's first point has: 0 for an interpolated profile, as the reference reads
/// kinkIndices there (the shared cases hold it to that), 1 for an approximated one, as the
/// schema documents them ([1, npoints]) and the reference reads them beside the 1-based
/// interpolatedPointsIndices.
std::vector<int> kinksOf(const schema::CurvePointListXYZType& list, const std::vector<int>& listIndex, int firstIndex) {
  std::vector<int> kinks;
  const std::string at = list.xpath + "/kinkIndices";
  if (list.kinkIndices)
    for (int index : indicesOf(*list.kinkIndices, at)) {
      if (index < firstIndex)
        throw Error(ErrorCode::InvalidModel, "index " + std::to_string(index) + " names no point of the list", {}, at);
      kinks.push_back(pointIndexOf(index - firstIndex, listIndex, at));
    }
  return kinks;
}

/// The list's parameter map: point index (into the points read) -> zeta.
std::map<int, double> pinnedParametersOf(const schema::CurvePointListXYZType& list, const std::vector<int>& listIndex) {
  std::map<int, double> pinned;
  if (!list.parameterMap) return pinned;
  const std::string at = list.parameterMap->xpath;
  const std::vector<int> indices = indicesOf(list.parameterMap->pointIndices, at + "/pointIndices");
  const std::vector<double> values = model::parseVector(list.parameterMap->paramOnCurve, at + "/paramOnCurve");
  if (indices.size() != values.size())
    throw Error(ErrorCode::InvalidModel, "pointIndices and paramOnCurve have different lengths", {}, at);
  for (std::size_t i = 0; i < indices.size(); ++i) pinned[pointIndexOf(indices[i], listIndex, at)] = values[i];
  return pinned;
}

/// The reference's half profile made whole: the points mirrored in y back to the first one
/// (the last given point not repeated where it lies on the symmetry plane), kinks and pinned
/// parameters mirrored with them. The given half ends at zeta 0.5 of the whole unless pinned.
void mirrorHalf(std::vector<gp_Pnt>& points, std::vector<int>& kinks, std::map<int, double>& pinned,
                const std::string& xpath) {
  constexpr double kOnThePlane = 1e-6;
  if (std::abs(points.front().Y()) > kOnThePlane)
    throw Error(ErrorCode::InvalidModel, "a half profile must start on the symmetry plane (y = 0)", {}, xpath);
  points.front().SetY(0.0);
  const int given = static_cast<int>(points.size());
  const double first = pinned.count(0) ? pinned[0] : 0.0;
  const double last = first + 2.0 * ((pinned.count(given - 1) ? pinned[given - 1] : 0.5) - first);
  for (int i = given - 1; i > 0; --i) {
    const gp_Pnt p = points[static_cast<std::size_t>(i)];
    if (i == given - 1 && std::abs(p.Y()) < kOnThePlane) continue;
    const int mirror = static_cast<int>(points.size());
    if (std::find(kinks.begin(), kinks.end(), i) != kinks.end()) kinks.push_back(mirror);
    if (pinned.count(i)) pinned[mirror] = last + first - pinned[i];
    points.emplace_back(p.X(), -p.Y(), p.Z());
  }
  points.push_back(points.front());
  pinned[0] = first;
  pinned[static_cast<int>(points.size()) - 1] = last;
}

/// The knots of an approximated profile: `poles` control points on uniform knots, with a knot
/// of full multiplicity at each kink's parameter, where the curve may turn a corner. As in
/// the reference, a kink within 1e-4 of a uniform knot takes that knot instead.
geometry::KnotVector approximationKnots(int poles, const std::vector<double>& kinkParameters) {
  constexpr double kSameKnot = 1e-4;
  geometry::KnotVector space = geometry::uniformKnots(0.0, 1.0, poles, kDegree);
  for (double t : kinkParameters) {
    const auto near = std::find_if(space.knots.begin(), space.knots.end(),
                                   [t](double knot) { return std::abs(knot - t) < kSameKnot; });
    if (near != space.knots.end()) {  // (an end knot keeps its full multiplicity)
      int& multiplicity = space.multiplicities[static_cast<std::size_t>(near - space.knots.begin())];
      multiplicity = std::max(multiplicity, kDegree);
    } else {
      const auto at = std::lower_bound(space.knots.begin(), space.knots.end(), t);
      const auto index = at - space.knots.begin();
      space.knots.insert(at, t);
      space.multiplicities.insert(space.multiplicities.begin() + index, kDegree);
    }
  }
  return space;
}

/// A curve whose ends part, closed by a straight piece from its end back to its start (as the
/// reference closes the wire of such a profile). The piece takes the end of the curve's last
/// knot span, in proportion to its length, and the rest of that span is moved before it, so
/// that every parameter before the last span (the pinned and mapped points') stays.
Handle(Geom_BSplineCurve) closedByStraightPiece(const Handle(Geom_BSplineCurve) & curve) {
  const double first = curve->FirstParameter(), last = curve->LastParameter();
  const double lastSpan = curve->Knot(curve->NbKnots() - 1);
  auto part = [&](double from, double to) {
    Handle(Geom_BSplineCurve) piece = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
    piece->Segment(from, to);
    return piece;
  };
  Handle(Geom_BSplineCurve) tail = part(lastSpan, last);
  const double tailLength = GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(tail));
  const double gap = curve->EndPoint().Distance(curve->StartPoint());
  const double split = lastSpan + (last - lastSpan) * tailLength / (tailLength + gap);
  geometry::setParameterRange(*tail, lastSpan, split);
  Handle(Geom_BSplineCurve) closing = geometry::straightLine(curve->EndPoint(), curve->StartPoint());
  geometry::setParameterRange(*closing, split, last);
  std::vector<Handle(Geom_BSplineCurve)> pieces{tail, closing};
  if (lastSpan > first) pieces.insert(pieces.begin(), part(first, lastSpan));
  return geometry::concatenateCurves(pieces);
}

/// The reference's approximationSettings (outside CPACS 3.5): a least-squares cubic with the
/// settings' number of poles instead of the interpolating curve, passing exactly through the
/// interpolatedPointsIndices and the kinks (corners allowed there), its sample parameters
/// corrected towards their feet five times at most (geometry::fitCorrectingParameters) while
/// the largest error falls by more than a thousandth, as the reference's fit of a fuselage
/// profile goes. A closed profile's seam point is approximated like any other; the seam
/// conditions (C0 to C2) compare the curve at its first and last point's current parameters,
/// as the reference's do, so that the corrections part the curve's ends a little (1 cm on
/// testProfileAirfoilApproximation's unit half disc); a straight piece closes it then.
Handle(Geom_BSplineCurve)
    approximatedCurve(const std::vector<gp_Pnt>& points, const std::vector<double>& parameters,
                      const std::vector<int>& kinks, bool closed, const model::ApproximationSettings& settings,
                      const std::vector<int>& listIndex, const std::string& xpath) {
  std::set<int> pinned(kinks.begin(), kinks.end());
  for (int index : settings.interpolated)
    pinned.insert(pointIndexOf(index, listIndex, xpath + "/approximationSettings/interpolatedPointsIndices"));
  const int last = static_cast<int>(points.size()) - 1;
  if (!closed) {  // a closed profile's seam is approximated like any point
    pinned.insert(0);
    pinned.insert(last);
  }
  std::vector<double> kinkParameters;
  for (int kink : kinks) kinkParameters.push_back(parameters[static_cast<std::size_t>(kink)]);
  geometry::InterpolationConstraints seam;
  if (closed) {
    seam.seamContinuity = 2;
    seam.freeSeam = true;
  }
  constexpr int kCorrections = 5;
  Handle(Geom_BSplineCurve) curve;
  try {
    // The reference judges each correction by the largest error, whatever the settings'
    // errorComputationMethod (which only names how it reports the error).
    curve = geometry::fitPointsCorrectingParameters(approximationKnots(settings.poles, kinkParameters), parameters,
                                                    points, pinned, geometry::FitError::Largest, seam, kCorrections,
                                                    geometry::SeamAt::EndPoints);
  } catch (const Error& error) {  // a singular system: too few distinct points between knots
    throw Error(error.code(), error.message(), {}, xpath + "/approximationSettings");
  }
  const bool parted = closed && curve->StartPoint().Distance(curve->EndPoint()) > kSamePoint;
  return parted ? closedByStraightPiece(curve) : curve;
}

FuselageProfile fromPointList(const schema::ProfileGeometryType& definition) {
  const schema::CurvePointListXYZType& list = *definition.pointList;
  const std::string xpath = list.xpath;
  std::vector<int> listIndex;
  FuselageProfile profile;
  std::vector<gp_Pnt> points = readPoints(list, xpath, listIndex, profile.warnings);
  const auto* settings = list.binding ? xml::firstChild(*list.binding, "approximationSettings") : nullptr;
  std::vector<int> kinks = kinksOf(list, listIndex, settings != nullptr ? 1 : 0);
  std::map<int, double> pinned = pinnedParametersOf(list, listIndex);
  profile.points = points;
  profile.mirroredHalf = isMirroredHalf(definition);
  if (profile.mirroredHalf) mirrorHalf(points, kinks, pinned, xpath);

  double size = 0.0;
  for (const gp_Pnt& a : points)
    for (const gp_Pnt& b : points) size = std::max(size, a.Distance(b));
  profile.closed = points.front().Distance(points.back()) < kClosureShare * size;
  if (profile.closed) {
    const gp_Pnt seam((points.front().XYZ() + points.back().XYZ()) / 2.0);
    points.front() = seam;
    points.back() = seam;
  }
  const std::vector<double> parameters = geometry::chordParameters(points, 0.5);
  // A parameter map pins points to parameters; the others keep their places between them.
  std::optional<std::vector<double>> mapped;
  if (!pinned.empty()) {
    const std::string at = list.parameterMap ? list.parameterMap->xpath : xpath;
    pinned.emplace(0, 0.0);
    pinned.emplace(static_cast<int>(points.size()) - 1, 1.0);
    mapped = mappedLinearly(parameters, pinned);
    for (std::size_t i = 1; i < mapped->size(); ++i)
      if (!((*mapped)[i] > (*mapped)[i - 1]))
        throw Error(ErrorCode::InvalidModel, "paramOnCurve does not increase along the points", {}, at);
  }
  if (settings != nullptr) {  // fitted in the mapped parameters, so that its knots follow the map
    const model::ApproximationSettings request =
        model::approximationSettings(*settings, xpath + "/approximationSettings", static_cast<int>(points.size()));
    profile.curve =
        approximatedCurve(points, mapped ? *mapped : parameters, kinks, profile.closed, request, listIndex, xpath);
  } else {
    profile.curve = geometry::interpolateWithCorners(points, parameters, kinks, profile.closed);
    if (mapped) profile.curve = geometry::reparametrisePiecewiseLinearly(*profile.curve, parameters, *mapped);
  }
  if (profile.mirroredHalf) {  // back to the given half, over the whole range
    profile.curve->Segment(profile.curve->FirstParameter(),
                           0.5 * (profile.curve->FirstParameter() + profile.curve->LastParameter()));
    geometry::setParameterRange(*profile.curve, 0.0, 1.0);
    profile.closed = false;
  }
  // Without pinned parameters (a half profile always has them: its ends), re-fitted on
  // uniform knots like the reference does: the loft through all profiles then needs few
  // knots, and the numbers agree with the reference's.
  if (pinned.empty() && settings == nullptr) profile.curve = geometry::refitOnUniformSpans(*profile.curve, parameters);
  return profile;
}

/// Where the parametrisation stands still at a quarter's end (an exponent of 1 makes the
/// superellipse's corners such points), the approximation can run a hair past the corner
/// and back, folding the profile onto itself; the pole next to such an end is put onto it.
void withoutOvershootAtTheEnds(Geom_BSplineCurve& quarter) {
  const int n = quarter.NbPoles();
  if (n < 3) return;
  for (const auto& [end, next, after] : {std::array<int, 3>{1, 2, 3}, std::array<int, 3>{n, n - 1, n - 2}}) {
    const gp_Pnt e = quarter.Pole(end);
    if (gp_Vec(e, quarter.Pole(next)).Dot(gp_Vec(e, quarter.Pole(after))) < 0.0) quarter.SetPole(next, e);
  }
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
  // Each quarter as the reference approximates it: piecewise Chebyshev, cubic, 1e-6; the
  // quarters joined with corners, so points at a given zeta agree with its numbers. Pieces
  // are halved down to 2^-14 of a quarter: where an exponent below 1 makes a sharp tip, ten
  // halvings left the curve 1e-4 of the width off there, fifteen 4e-6, and the reference's
  // figures agree better too (docs/conformance.md).
  constexpr int kDepth = 15;
  std::vector<Handle(Geom_BSplineCurve)> quarters;
  for (int q = 0; q < 4; ++q) {
    quarters.push_back(geometry::approximateByChebyshevPieces(at, 0.25 * q, 0.25 * (q + 1), {3, 1e-6, kDepth}));
    withoutOvershootAtTheEnds(*quarters.back());
  }
  FuselageProfile profile;
  profile.curve = geometry::concatenateCurves(quarters);
  return profile;
}

/// A number as an error message shows it (six significant digits).
std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// The rectangle of width 1 and height heightToWidthRatio with rounded corners, from the
/// top centre towards +y; zeta is the share of the length travelled.
///
/// Each straight piece and each quarter arc is one cubic span, joined with corners, as the
/// reference draws it: how a profile's length is shared among its poles is not the profile's
/// business alone, since the guided skin fills each cell from the poles of its boundaries
/// (OCCT's Coons filling) and the smooth skin spaces its sections by the poles' distances. A
/// rectangle of dense samples, the same shape, moved a guided section's area by 4e-3 and
/// unguided points by 2 mm from the reference's (docs/conformance.md). A quarter arc is the
/// cubic with the circle's end points and end tangents and its middle on the circle
/// (inner poles 4/3·tan(22.5°) of the radius along the tangents): it stays within 2.7e-4 of
/// the radius outside the circle, ten times closer than a cubic linear in angle.
FuselageProfile rectangle(const schema::RectangleProfileType& shape) {
  const double h = shape.heightToWidthRatio / 2.0, c = shape.cornerRadius.value_or(0.0);
  if (!(c >= 0.0 && c < 0.5))
    throw Error(ErrorCode::InvalidModel,
                "the corner radius " + numberText(c) + " lies outside [0, 0.5) of the rectangle's width", {},
                shape.xpath + "/cornerRadius");
  if (c > h)
    throw Error(ErrorCode::InvalidModel,
                "the corner radius " + numberText(c) + " is more than half the rectangle's height (" + numberText(h) +
                    "): its rounded corners would overlap",
                {}, shape.xpath + "/cornerRadius");
  const double arcLength = M_PI * c / 2.0, kappa = 4.0 / 3.0 * std::tan(M_PI / 8.0);
  // The corners of the path (top centre, then clockwise seen from +x), each with the
  // direction in which the path leaves it; an arc joins two of them where c > 0.
  struct Station {
    gp_Pnt point;
    gp_Vec along;
  };
  const gp_Vec right(0, 1, 0), down(0, 0, -1), left(0, -1, 0), up(0, 0, 1);
  const std::vector<Station> stations = {{{0, 0, h}, right},       {{0, 0.5 - c, h}, right}, {{0, 0.5, h - c}, down},
                                         {{0, 0.5, -h + c}, down}, {{0, 0.5 - c, -h}, left}, {{0, -0.5 + c, -h}, left},
                                         {{0, -0.5, -h + c}, up},  {{0, -0.5, h - c}, up},   {{0, -0.5 + c, h}, right},
                                         {{0, 0, h}, right}};
  // Each piece between two stations as its four poles: a straight piece's evenly spaced, an
  // arc's inner ones kappa·c along the tangents. Pieces of no length (c = 0, c = h) are left out.
  std::vector<std::vector<gp_Pnt>> spans;
  std::vector<double> lengths;
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < stations.size(); ++i) {
    const gp_Pnt &a = stations[i].point, &b = stations[i + 1].point;
    const bool arc = stations[i].along.Dot(stations[i + 1].along) < 0.5;
    const double length = arc ? arcLength : a.Distance(b);
    if (length <= 1e-12) continue;
    const gp_Vec inA = arc ? stations[i].along * (kappa * c) : gp_Vec(a, b) / 3.0;
    const gp_Vec inB = arc ? stations[i + 1].along * (kappa * c) : gp_Vec(a, b) / 3.0;
    spans.push_back({a, a.Translated(inA), b.Translated(-inB), b});
    lengths.push_back(length);
    total += length;
  }
  std::vector<Handle(Geom_BSplineCurve)> pieces;
  double start = 0.0;
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const double end = i + 1 == spans.size() ? 1.0 : start + lengths[i] / total;
    pieces.push_back(geometry::makeCurve(geometry::uniformKnots(start, end, 4, 3), geometry::toMatrix(spans[i])));
    start = end;
  }
  FuselageProfile profile;
  profile.curve = geometry::concatenateCurves(pieces);
  profile.standardGuideScale = shape.heightToWidthRatio;
  return profile;
}

}  // namespace

double FuselageProfile::guideScale(const Eigen::Affine3d& transform) const {
  if (points.empty()) return standardGuideScale;
  std::vector<Eigen::Vector3d> placed;
  for (const gp_Pnt& p : points) placed.push_back(transform * Eigen::Vector3d(p.X(), p.Y(), p.Z()));
  if (mirroredHalf) return (placed.back() - placed.front()).norm();  // the half's ends lie on the plane
  const Eigen::Vector3d middle = 0.5 * (placed.front() + placed.back());
  double farthest = 0.0;
  for (const auto& p : placed) farthest = std::max(farthest, (p - middle).norm());
  return farthest;
}

FuselageProfile FuselageProfile::fromDefinition(const schema::ProfileGeometryType& definition) {
  if (definition.pointList) return fromPointList(definition);
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
