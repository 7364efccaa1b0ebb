#include "wing_profile.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <utility>

#include <Bnd_Box2d.hxx>
#include <gp_Vec.hxx>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/chebyshev_approximation.h"
#include "airshape/geometry/curve_approximation.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/profile_outline.h"
#include "airshape/model/approximation_settings.h"
#include "airshape/model/cst_airfoil.h"
#include "airshape/model/placement.h"
#include "airshape/xml/text.h"
#include "naca_four_digit.h"

namespace airshape::wing {

namespace {

constexpr double kSamePoint = 1e-7;

/// The part [from, to] of a curve (to < from reverses it) as a B-spline over [0, 1].
Handle(Geom_BSplineCurve) piece(const Geom_BSplineCurve& curve, double from, double to) {
  Handle(Geom_BSplineCurve) part = Handle(Geom_BSplineCurve)::DownCast(curve.Copy());
  part->Segment(std::min(from, to), std::max(from, to));
  if (to < from) part->Reverse();
  geometry::setParameterRange(*part, 0.0, 1.0);
  return part;
}

/// Puts a point list in the order trailing edge → lower side → leading edge → upper side:
/// reversed (and true returned) when its lowest point comes after its highest.
bool orderFromLowerSide(std::vector<gp_Pnt>& points) {
  const auto byZ = [](const gp_Pnt& a, const gp_Pnt& b) { return a.Z() < b.Z(); };
  if (!(std::min_element(points.begin(), points.end(), byZ) > std::max_element(points.begin(), points.end(), byZ)))
    return false;
  std::reverse(points.begin(), points.end());
  return true;
}

/// The leading edge: the point farthest from the middle of the first and last points.
std::size_t leadingEdgeIndex(const std::vector<gp_Pnt>& points) {
  const gp_Pnt middle((points.front().XYZ() + points.back().XYZ()) / 2.0);
  std::size_t index = 0;
  double farthest = -1.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = points[i].Distance(middle);
    if (d > farthest) {
      farthest = d;
      index = i;
    }
  }
  return index;
}

/// The airfoil's points with its zig-zags' loops taken out (geometry::zigZags: optimisers write
/// airfoils whose points step back and forth by micrometres at the leading edge; lofted
/// through, such a loop makes the wing's wire cross itself), each said in `warnings`.
std::vector<gp_Pnt> untangled(const std::vector<gp_Pnt>& points, std::vector<std::string>& warnings) {
  std::vector<gp_Pnt2d> outline;  // in the airfoil's plane
  for (const gp_Pnt& point : points) outline.emplace_back(point.X(), point.Z());
  const std::vector<geometry::ZigZag> loops = geometry::zigZags(outline, kSamePoint);
  if (loops.empty()) return points;
  Bnd_Box2d box;
  for (const gp_Pnt2d& corner : outline) box.Add(corner);
  for (const geometry::ZigZag& loop : loops) {
    std::ostringstream what;
    what << std::setprecision(2) << "the points zig-zag across their own outline (its sides from point "
         << loop.firstSide + 1 << " and from point " << loop.lastSide + 1 << " cross by "
         << loop.depth / std::sqrt(box.SquareExtent()) << " of the profile's size): points " << loop.firstSide + 2
         << " to " << loop.lastSide + 1 << " replaced by the point where those sides cross";
    warnings.push_back(what.str());
  }
  return geometry::withoutZigZags(points, loops);
}

}  // namespace

WingProfile WingProfile::fromDefinition(const schema::ProfileGeometryType& definition) {
  if (definition.pointList) return fromPointList(*definition.pointList, definition.xpath + "/pointList");
  if (definition.cst2D) return fromCst(*definition.cst2D, definition.xpath + "/cst2D");
  if (const auto* naca = definition.binding ? xml::firstChild(*definition.binding, "nacaProfile") : nullptr)
    return fromNaca(*naca, definition.xpath + "/nacaProfile");
  // The schema shares the profile type with fuselages, whose rectangle and superellipse are
  // drawn in y and z: no leading or trailing edge (the reference builds none either).
  if (definition.standardProfile)
    throw Error(
        ErrorCode::InvalidModel,
        "a standardProfile (rectangle or superellipse) is a fuselage profile; a wing airfoil needs a pointList, "
        "cst2D or nacaProfile",
        {}, definition.xpath + "/standardProfile");
  throw Error(ErrorCode::InvalidModel,
              "wing airfoil '" + definition.uID + "' has neither pointList nor cst2D nor a 4-digit nacaProfile", {},
              definition.xpath);
}

WingProfile WingProfile::fromNaca(const xercesc::DOMElement& naca, const std::string& xpath) {
  const auto* codeElement = xml::firstChild(naca, "naca4DigitCode");
  const std::string code = codeElement ? xml::text(*codeElement) : "";
  if (code.size() != 4 || !std::all_of(code.begin(), code.end(), [](char c) { return c >= '0' && c <= '9'; }))
    throw Error(ErrorCode::InvalidModel, "only 4-digit NACA codes are supported (got '" + code + "')", {}, xpath);
  double trailingEdge = 0.0;  // closed unless a thickness is given
  if (const auto* te = xml::firstChild(naca, "trailingEdgeThickness"))
    trailingEdge = model::parseVector(xml::text(*te), xpath + "/trailingEdgeThickness").at(0);
  const NacaFourDigit airfoil((code[0] - '0') / 100.0, (code[1] - '0') / 10.0, std::stoi(code.substr(2)) / 100.0,
                              trailingEdge);
  if (!(airfoil.thickness() > 0.0)) throw Error(ErrorCode::InvalidModel, "a NACA airfoil needs a thickness", {}, xpath);

  WingProfile profile;
  profile.blunt_ = trailingEdge > 0.0;
  profile.leadingEdge_ = gp_Pnt(0, 0, 0);
  profile.trailingEdge_ = gp_Pnt(1, 0, 0);
  profile.approximateSides([airfoil](double xsi) { return airfoil.side(NacaFourDigit::chordwise(xsi), 1.0); },
                           [airfoil](double xsi) { return airfoil.side(NacaFourDigit::chordwise(xsi), -1.0); }, 3);
  profile.lowerXsiFromTrailingEdge_ = true;
  return profile;
}

WingProfile WingProfile::fromPointList(const schema::CurvePointListXYZType& list, const std::string& xpath) {
  const std::vector<double> x = model::parseVector(list.x, xpath + "/x"), y = model::parseVector(list.y, xpath + "/y"),
                            z = model::parseVector(list.z, xpath + "/z");
  if (x.size() != y.size() || x.size() != z.size())
    throw Error(ErrorCode::InvalidModel, "x, y and z have different lengths", {}, xpath);
  std::vector<gp_Pnt> points;
  for (std::size_t i = 0; i < x.size(); ++i) points.emplace_back(x[i], y[i], z[i]);
  std::vector<std::string> warnings;
  points = untangled(points, warnings);
  std::vector<gp_Pnt2d> outline;  // in the airfoil's plane
  for (const gp_Pnt& point : points) outline.emplace_back(point.X(), point.Z());
  if (const auto crossing = geometry::requireProfileOutline(outline, kSamePoint, {}, xpath))
    warnings.push_back(*crossing);
  const auto* settings = list.binding ? xml::firstChild(*list.binding, "approximationSettings") : nullptr;
  WingProfile profile = settings
                            ? fromApproximatedPoints(std::move(points), *settings, xpath + "/approximationSettings")
                            : fromPoints(std::move(points), xpath);
  for (const std::string& warning : warnings) profile.warnings_.push_back({Problem::Severity::Warning, xpath, warning});
  return profile;
}

WingProfile WingProfile::fromApproximatedPoints(std::vector<gp_Pnt> points, const xercesc::DOMElement& settings,
                                                const std::string& xpath) {
  const model::ApproximationSettings request =
      model::approximationSettings(settings, xpath, static_cast<int>(points.size()));
  const int last = static_cast<int>(points.size()) - 1;
  const bool reversed = orderFromLowerSide(points);
  std::set<int> pinned = {0, last};
  for (int index : request.interpolated) pinned.insert(reversed ? last - index : index);
  if (points.size() < 3) throw Error(ErrorCode::InvalidModel, "an airfoil needs at least three points", {}, xpath);
  const auto le = static_cast<int>(leadingEdgeIndex(points));
  WingProfile profile = withChord(points, static_cast<std::size_t>(le));
  if (le == 0 || le == last) throw Error(ErrorCode::InvalidModel, "the leading edge is an end point", {}, xpath);
  pinned.insert(le);

  // Centripetal parameters, stretched on either side so that the leading edge is at 0.5.
  std::vector<double> parameters = geometry::chordParameters(points, 0.5);
  const double tLe = parameters[static_cast<std::size_t>(le)];
  for (double& t : parameters) t = t <= tLe ? 0.5 * t / tLe : 0.5 + 0.5 * (t - tLe) / (1.0 - tLe);

  // The pinned points are constraints, the others samples whose parameters get corrected.
  Handle(Geom_BSplineCurve) curve;
  try {
    curve = geometry::fitPointsCorrectingParameters(geometry::uniformKnots(0.0, 1.0, request.poles, 3), parameters,
                                                    points, pinned, request.measure);
  } catch (const Error& error) {  // a singular system: too few distinct points between knots
    throw Error(error.code(), error.message(), {}, xpath);
  }
  profile.takeWholeCurve(curve, 0.5);
  return profile;
}

WingProfile WingProfile::withChord(const std::vector<gp_Pnt>& points, std::size_t leIndex) {
  WingProfile profile;
  const gp_Pnt first = points.front(), last = points.back();
  profile.blunt_ = first.Distance(last) >= kSamePoint;
  gp_Pnt middle((first.XYZ() + last.XYZ()) / 2.0), le = points[leIndex];
  le.SetY(0.0);
  middle.SetY(0.0);
  if (profile.blunt_) {
    const gp_Vec chord(le, middle);
    auto share = [&](const gp_Pnt& p) { return gp_Vec(le, p).Dot(chord) / chord.SquareMagnitude(); };
    const double aft = std::min(share(first), share(last));
    profile.trailingEdge_ = gp_Pnt(le.XYZ() + aft * chord.XYZ());
  } else {
    profile.trailingEdge_ = first;
  }
  profile.leadingEdge_ = le;
  return profile;
}

WingProfile WingProfile::fromPoints(std::vector<gp_Pnt> points, const std::string& xpath) {
  if (points.size() < 3) throw Error(ErrorCode::InvalidModel, "an airfoil needs at least three points", {}, xpath);

  orderFromLowerSide(points);
  const std::size_t leIndex = leadingEdgeIndex(points);
  WingProfile profile = withChord(points, leIndex);

  // The curve: consecutive duplicates dropped, cubic through centripetal parameters.
  std::vector<gp_Pnt> kept;
  std::size_t keptLe = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!kept.empty() && kept.back().Distance(points[i]) < kSamePoint) continue;
    if (i == leIndex) keptLe = kept.size();
    kept.push_back(points[i]);
  }
  const std::vector<double> parameters = geometry::chordParameters(kept, 0.5);
  Handle(Geom_BSplineCurve) curve = geometry::interpolateCurve(kept, parameters, 3);
  // Both sides run whole to the trailing edge, also where it is skewed: the reference means
  // to cut the side that reaches further aft square to the chord, but its cut never takes
  // effect, and its numbers are those of the whole sides (see docs/wing.md).
  profile.takeWholeCurve(curve, parameters[keptLe]);
  return profile;
}

void WingProfile::takeWholeCurve(const Handle(Geom_BSplineCurve) & curve, double leadingEdge) {
  upper_ = [curve, leadingEdge](double xsi) { return curve->Value(leadingEdge + xsi * (1.0 - leadingEdge)); };
  lower_ = [curve, leadingEdge](double xsi) { return curve->Value(leadingEdge - xsi * leadingEdge); };
  upperCurve_ = piece(*curve, leadingEdge, 1.0);
  lowerCurve_ = piece(*curve, leadingEdge, 0.0);
  whole_ = curve;
}

std::vector<Handle(Geom_BSplineCurve)> WingProfile::outline() const {
  if (!whole_.IsNull()) return {whole_};
  Handle(Geom_BSplineCurve) lower = Handle(Geom_BSplineCurve)::DownCast(lowerCurve_->Copy());
  lower->Reverse();
  return {lower, upperCurve_};
}

WingProfile WingProfile::fromCst(const schema::Cst2DType& cst, const std::string& xpath) {
  const model::CstAirfoil airfoil = model::CstAirfoil::read(cst, xpath);
  WingProfile profile;
  profile.blunt_ = airfoil.bluntTrailingEdge;
  profile.leadingEdge_ = gp_Pnt(0, 0, 0);
  profile.trailingEdge_ = gp_Pnt(1, 0, 0);
  profile.approximateSides(airfoil.upper, airfoil.lower, 4);
  return profile;
}

void WingProfile::approximateSides(const Side& upper, const Side& lower, int degree) {
  const geometry::ChebyshevSettings settings{degree, 1e-5, 10};
  upperCurve_ = geometry::approximateByChebyshevPieces(upper, 0.0, 1.0, settings);
  lowerCurve_ = geometry::approximateByChebyshevPieces(lower, 0.0, 1.0, settings);
  upper_ = [curve = upperCurve_](double xsi) { return curve->Value(xsi); };
  lower_ = [curve = lowerCurve_](double xsi) { return curve->Value(xsi); };
}

gp_Pnt WingProfile::upper(double xsi) const { return upper_(xsi); }

gp_Pnt WingProfile::lower(double xsi) const { return lower_(lowerXsiFromTrailingEdge_ ? 1.0 - xsi : xsi); }

}  // namespace airshape::wing
