#include "airshape/model/guide_curves.h"

#include <algorithm>
#include <iterator>
#include <unordered_map>

#include <GeomAPI_Interpolate.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfBoolean.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfVec.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/topological_sort.hpp>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/model/placement.h"
#include "airshape/xml/text.h"

namespace airshape::model {

namespace {

using schema::GuideCurveType;
using Continuity = schema::GuideCurveTypeContinuity;

/// A guide curve profile: (alpha, beta, gamma) per point.
struct GuideProfile {
  std::vector<gp_XYZ> points;
};

GuideProfile readGuideProfile(const schema::CpacsType& cpacs, const GuideCurveType& curve) {
  if (cpacs.vehicles && cpacs.vehicles->profiles && cpacs.vehicles->profiles->guideCurves)
    for (const auto& profile : cpacs.vehicles->profiles->guideCurves->guideCurveProfile) {
      if (profile.uID != curve.guideCurveProfileUID) continue;
      if (!profile.pointList)
        throw Error(ErrorCode::InvalidModel, "the guide curve profile has no pointList", {}, profile.xpath);
      const std::string at = profile.pointList->xpath;
      const auto a = parseVector(profile.pointList->rX, at + "/rX"), b = parseVector(profile.pointList->rY, at + "/rY"),
                 c = parseVector(profile.pointList->rZ, at + "/rZ");
      if (a.size() != b.size() || a.size() != c.size())
        throw Error(ErrorCode::InvalidModel, "rX, rY and rZ have different lengths", {}, at);
      // rY is where along the segment each point lies: going back, the guide would fold the skin.
      for (std::size_t i = 1; i < b.size(); ++i)
        if (!(b[i] > b[i - 1]))
          throw Error(ErrorCode::InvalidModel,
                      "rY must increase from point to point (the points run from the inner "
                      "to the outer section)",
                      {}, at + "/rY");
      GuideProfile result;
      for (std::size_t i = 0; i < a.size(); ++i) result.points.emplace_back(a[i], b[i], c[i]);
      return result;
    }
  throw Error(ErrorCode::InvalidModel,
              "guideCurveProfileUID '" + curve.guideCurveProfileUID + "' names no guide curve profile", {},
              curve.xpath + "/guideCurveProfileUID");
}

/// A number the schema has no place for, read from the element itself (the reference's
/// fromParameter/toParameter extension).
std::optional<double> extensionNumber(const GuideCurveType& curve, const char* name) {
  if (!curve.binding) return std::nullopt;
  const auto* element = xml::firstChild(*curve.binding, name);
  if (!element) return std::nullopt;
  const std::vector<double> values = parseVector(xml::text(*element), curve.xpath + "/" + name);
  if (values.size() != 1) throw Error(ErrorCode::InvalidModel, "expected one number", {}, curve.xpath + "/" + name);
  return values.front();
}

/// Where a root guide curve starts on its first profile.
ProfilePosition startOf(const GuideCurveType& curve) {
  if (curve.fromRelativeCircumference)
    return {finite(*curve.fromRelativeCircumference, curve.xpath + "/fromRelativeCircumference"), false};
  return {*extensionNumber(curve, "fromParameter"), true};
}

/// Where a guide curve piece ends on its outer profile.
ProfilePosition endOf(const GuideCurveType& curve) {
  if (const auto parameter = extensionNumber(curve, "toParameter")) return {*parameter, true};
  return {finite(curve.toRelativeCircumference, curve.xpath + "/toRelativeCircumference"), false};
}

/// One piece of a guide curve: the curve definition in segment `segment` and its points.
struct Piece {
  const GuideCurveType* definition = nullptr;
  std::size_t segment = 0;
  ProfilePosition from;
  std::vector<gp_Pnt> points;
  std::vector<double> parameters;
};

/// The chain of pieces of one root, one per segment.
std::vector<Piece> chainOf(const GuideCurveType& root, const std::vector<const schema::GuideCurvesType*>& perSegment) {
  std::vector<Piece> chain = {{&root, 0, startOf(root), {}, {}}};
  for (std::size_t segment = 1; segment < perSegment.size(); ++segment) {
    const GuideCurveType* next = nullptr;
    if (perSegment[segment])
      for (const auto& curve : perSegment[segment]->guideCurve)
        if (curve.fromGuideCurveUID && *curve.fromGuideCurveUID == chain.back().definition->uID) {
          if (next)
            throw Error(ErrorCode::InvalidModel, "two guide curves continue '" + chain.back().definition->uID + "'", {},
                        curve.xpath);
          next = &curve;
        }
    if (!next)
      throw Error(ErrorCode::InvalidModel,
                  "no guide curve of the next segment continues this one (every guide curve must run through all "
                  "segments)",
                  {}, chain.back().definition->xpath);
    chain.push_back({next, segment, endOf(*chain.back().definition), {}, {}});
  }
  return chain;
}

/// The piece's points [P0, Q_1 .. Q_m, P1] and their parameters within [from, to].
void placePiece(Piece& piece, const GuideProfile& profile, const GuideCurveSections& sections, double from, double to) {
  const GuideCurveType& curve = *piece.definition;
  const std::size_t k = piece.segment;
  gp_Pnt p0, p1;
  try {
    p0 = sections.pointAt(k, piece.from);
    p1 = sections.pointAt(k + 1, endOf(curve));
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), error.message(), {}, curve.xpath);  // the component cannot place this curve's ends
  }
  gp_Vec x = sections.defaultXDirection;
  if (const auto& given = curve.rXDirection)
    x = gp_Vec(finite(given->x, given->xpath + "/x"), finite(given->y, given->xpath + "/y"),
               finite(given->z, given->xpath + "/z"));
  const gp_Vec chord(p0, p1);
  if (x.Magnitude() < Precision::Confusion() || chord.Magnitude() < Precision::Confusion() ||
      x.Crossed(chord).Magnitude() < Precision::Confusion() * x.Magnitude() * chord.Magnitude())
    throw Error(ErrorCode::InvalidModel,
                "the guide curve's ends coincide or lie along its rXDirection, so its profile has no plane", {},
                curve.xpath);
  x.Normalize();
  const gp_Vec z = x.Crossed(chord).Normalized();
  const double scaleIn = sections.scale(k), scaleOut = sections.scale(k + 1);
  piece.points = {p0};
  for (std::size_t i = 0; i < profile.points.size(); ++i) {
    const double alpha = profile.points[i].X(), beta = profile.points[i].Y(), gamma = profile.points[i].Z();
    if ((i == 0 && beta <= 0.0) || (i + 1 == profile.points.size() && beta >= 1.0))
      throw Error(ErrorCode::InvalidModel,
                  "the guide curve profile's rY must lie strictly between 0 and 1 (the ends are the sections' points)",
                  {}, curve.xpath + "/guideCurveProfileUID");
    const double s = (1.0 - beta) * scaleIn + beta * scaleOut;
    piece.points.emplace_back(p0.XYZ() + beta * chord.XYZ() + s * (alpha * x.XYZ() + gamma * z.XYZ()));
  }
  piece.points.push_back(p1);
  piece.parameters = geometry::chordParameters(piece.points, 0.5);
  for (double& t : piece.parameters) t = from + (to - from) * t;
}

/// A run of pieces interpolated as one curve, with the derivatives its ends must have.
struct Part {
  std::size_t firstPiece = 0, endPiece = 0;  ///< pieces [firstPiece, endPiece)
  std::optional<gp_Vec> startDerivative, endDerivative;
  Handle(Geom_BSplineCurve) curve;
};

/// OCCT's cubic through the points at the parameters with the given end derivatives, or
/// null where OCCT cannot build one (two points closer than 1e-7).
Handle(Geom_BSplineCurve)
    cubicThrough(const std::vector<gp_Pnt>& points, const std::vector<double>& parameters,
                 const std::optional<gp_Vec>& startDerivative, const std::optional<gp_Vec>& endDerivative) {
  const int count = static_cast<int>(points.size());
  Handle(TColgp_HArray1OfPnt) occPoints = new TColgp_HArray1OfPnt(1, count);
  Handle(TColStd_HArray1OfReal) occParameters = new TColStd_HArray1OfReal(1, count);
  for (int i = 0; i < count; ++i) {
    occPoints->SetValue(i + 1, points[static_cast<std::size_t>(i)]);
    occParameters->SetValue(i + 1, parameters[static_cast<std::size_t>(i)]);
  }
  // Tangents are loaded even when none is prescribed: that makes every part of three points
  // or more a cubic with a knot at each point, whose free ends take OCCT's estimated
  // tangents, as in the reference. Without them OCCT builds three points as one parabola
  // span: the same curve for collinear points, but other poles, and the Coons patches are
  // filled from the poles (CONVENTIONS §4.2).
  TColgp_Array1OfVec tangents(1, count);
  Handle(TColStd_HArray1OfBoolean) given = new TColStd_HArray1OfBoolean(1, count, false);
  for (int i = 1; i <= count; ++i) tangents(i) = gp_Vec(0, 0, 0);
  if (startDerivative) {
    tangents(1) = *startDerivative;
    given->SetValue(1, true);
  }
  if (endDerivative) {
    tangents(count) = *endDerivative;
    given->SetValue(count, true);
  }
  try {
    GeomAPI_Interpolate interpolation(occPoints, occParameters, false, Precision::Confusion());
    if (count >= 3 || startDerivative || endDerivative) interpolation.Load(tangents, given, false);
    interpolation.Perform();
    return interpolation.IsDone() ? interpolation.Curve() : nullptr;
  } catch (const Standard_Failure&) {
    return nullptr;
  }
}

Handle(Geom_BSplineCurve) interpolatePart(const std::vector<Piece>& pieces, const Part& part) {
  std::vector<gp_Pnt> points;
  std::vector<double> parameters;
  for (std::size_t p = part.firstPiece; p < part.endPiece; ++p)
    for (std::size_t i = p == part.firstPiece ? 0 : 1; i < pieces[p].points.size(); ++i) {
      points.push_back(pieces[p].points[i]);
      parameters.push_back(pieces[p].parameters[i]);
    }
  Handle(Geom_BSplineCurve) curve = cubicThrough(points, parameters, part.startDerivative, part.endDerivative);
  if (curve.IsNull())
    throw Error(ErrorCode::InvalidModel,
                "the guide curve's points cannot be interpolated: two of them coincide (check the guide curve "
                "profile's rY values)",
                {}, pieces[part.firstPiece].definition->xpath);
  return curve;
}

/// Whether the part starts with the end derivative of the part before ("C1/C2 from previous";
/// C1 and C2 are treated alike: the first derivative is matched).
bool takesFromPrevious(const std::vector<Piece>& pieces, const Part& part) {
  const Continuity c = pieces[part.firstPiece].definition->continuity.value_or(Continuity::C0);
  return c == Continuity::C1FromPrevious || c == Continuity::C2FromPrevious;
}

/// Whether the part before must end with this part's start derivative ("to previous").
bool givesToPrevious(const std::vector<Piece>& pieces, const Part& part) {
  const Continuity c = pieces[part.firstPiece].definition->continuity.value_or(Continuity::C0);
  return c == Continuity::C1ToPrevious || c == Continuity::C2ToPrevious;
}

/// Interpolates the parts in an order where every part whose end derivative another one
/// takes comes first (a topological sort of that dependency), then joins them.
Handle(Geom_BSplineCurve) joinParts(const std::vector<Piece>& pieces, std::vector<Part>& parts) {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;
  Graph dependencies(parts.size());
  for (std::size_t j = 1; j < parts.size(); ++j) {
    if (takesFromPrevious(pieces, parts[j])) boost::add_edge(j - 1, j, dependencies);
    if (givesToPrevious(pieces, parts[j])) boost::add_edge(j, j - 1, dependencies);
  }
  std::vector<std::size_t> reversedOrder;
  boost::topological_sort(dependencies, std::back_inserter(reversedOrder));
  for (auto it = reversedOrder.rbegin(); it != reversedOrder.rend(); ++it) {
    const std::size_t j = *it;
    Part& part = parts[j];
    part.curve = interpolatePart(pieces, part);
    // Hand this part's end derivatives to the neighbours that take them.
    if (j + 1 < parts.size() && takesFromPrevious(pieces, parts[j + 1]))
      parts[j + 1].startDerivative = part.curve->DN(part.curve->LastParameter(), 1);
    if (j > 0 && givesToPrevious(pieces, part))
      parts[j - 1].endDerivative = part.curve->DN(part.curve->FirstParameter(), 1);
  }
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (const Part& part : parts) curves.push_back(part.curve);
  return geometry::concatenateCurves(curves);
}

}  // namespace

bool hasGuideCurves(const std::vector<const schema::GuideCurvesType*>& perSegment) {
  return std::any_of(perSegment.begin(), perSegment.end(),
                     [](const auto* curves) { return curves && !curves->guideCurve.empty(); });
}

std::vector<GuideCurve> buildGuideCurves(const schema::CpacsType& cpacs,
                                         const std::vector<const schema::GuideCurvesType*>& perSegment,
                                         const GuideCurveSections& sections) {
  std::vector<GuideCurve> result;
  if (perSegment.empty() || !perSegment.front()) return result;
  std::vector<gp_Pnt> centres;
  for (std::size_t k = 0; k < sections.count; ++k) centres.push_back(sections.centre(k));
  const std::vector<double> sectionParameters = geometry::chordParameters(centres, 0.5);
  for (std::size_t segment = 1; segment < perSegment.size(); ++segment)
    if (perSegment[segment])
      for (const auto& curve : perSegment[segment]->guideCurve)
        if (!curve.fromGuideCurveUID)
          throw Error(ErrorCode::InvalidModel,
                      "a guide curve that starts after the first segment (no fromGuideCurveUID) cannot run through "
                      "all segments",
                      {}, curve.xpath);

  for (const auto& root : perSegment.front()->guideCurve) {
    if (!root.fromRelativeCircumference && !extensionNumber(root, "fromParameter"))
      throw Error(ErrorCode::InvalidModel, "a guide curve of the first segment needs fromRelativeCircumference", {},
                  root.xpath);
    std::vector<Piece> pieces = chainOf(root, perSegment);
    std::vector<Part> parts;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      placePiece(pieces[p], readGuideProfile(cpacs, *pieces[p].definition), sections, sectionParameters[p],
                 sectionParameters[p + 1]);
      if (p == 0 || pieces[p].definition->continuity) parts.push_back({p, p + 1, {}, {}, {}});
      parts.back().endPiece = p + 1;
    }
    std::vector<ProfilePosition> positions;
    for (const Piece& piece : pieces) positions.push_back(piece.from);
    positions.push_back(endOf(*pieces.back().definition));
    std::vector<bool> smoothAt(pieces.size() + 1, false);
    for (std::size_t p = 1; p < pieces.size(); ++p) {
      const auto& continuity = pieces[p].definition->continuity;
      smoothAt[p] = !continuity || *continuity == Continuity::C2FromPrevious || *continuity == Continuity::C2ToPrevious;
    }
    result.push_back({root.uID, joinParts(pieces, parts), sectionParameters, positions, smoothAt});
  }
  return result;
}

}  // namespace airshape::model
