#include "nacelle_profile.h"

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomConvert_CompCurveToBSplineCurve.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/chebyshev_approximation.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/model/cst_airfoil.h"
#include "airshape/model/placement.h"

namespace airshape::nacelle {

namespace {

constexpr double kJoinTolerance = 1e-10;

const schema::ProfileGeometry2DType* findProfile(const Configuration& configuration, const std::string& uid,
                                                 bool curveProfile) {
  const auto& vehicles = configuration.cpacs().vehicles;
  if (!vehicles || !vehicles->profiles) return nullptr;
  const schema::ProfilesType& profiles = *vehicles->profiles;
  if (curveProfile) {
    if (profiles.curveProfiles)
      for (const auto& profile : profiles.curveProfiles->curveProfile)
        if (profile.uID == uid) return &profile;
  } else if (profiles.nacelleProfiles) {
    for (const auto& profile : profiles.nacelleProfiles->nacelleProfile)
      if (profile.uID == uid) return &profile;
  }
  return nullptr;
}

/// The sides of a `cst2D` profile as curves, made as the wing's CST airfoils are, but within about
/// 1e-9 of the chord instead of 1e-5 (the wing matches the reference's points; here the cowl's
/// volume follows the formula to 1e-7 with it): the lower side from the trailing edge to the leading
/// edge and the upper side on to the trailing edge, in the x-z plane.
void cstSides(const schema::Cst2DType& cst, const std::string& xpath, Handle(Geom_BSplineCurve) & lower,
              Handle(Geom_BSplineCurve) & upper) {
  const model::CstAirfoil airfoil = model::CstAirfoil::read(cst, xpath);
  const geometry::ChebyshevSettings settings{4, 1e-9, 20};
  upper = geometry::approximateByChebyshevPieces(airfoil.upper, 0.0, 1.0, settings);
  lower = geometry::approximateByChebyshevPieces(airfoil.lower, 0.0, 1.0, settings);
  lower->Reverse();
}

/// Two curves that meet, one after the other, as one B-spline (C0 where they meet).
Handle(Geom_BSplineCurve) joined(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & second) {
  GeomConvert_CompCurveToBSplineCurve joiner(first);
  if (!joiner.Add(second, kJoinTolerance))
    throw Error(ErrorCode::InvalidModel, "the profile's sides do not meet at the leading edge");
  return joiner.BSplineCurve();
}

}  // namespace

double parameterAtLengthShare(const Handle(Geom_BSplineCurve) & curve, double share) {
  GeomAdaptor_Curve adaptor(curve);
  const double first = curve->FirstParameter(), last = curve->LastParameter();
  const double length = GCPnts_AbscissaPoint::Length(adaptor, first, last);
  if (share <= 0.0) return first;
  if (share >= 1.0) return last;
  GCPnts_AbscissaPoint at(adaptor, share * length, first);
  if (!at.IsDone()) throw Error(ErrorCode::InvalidModel, "a curve coordinate cannot be found on the profile");
  return at.Parameter();
}

Handle(Geom_BSplineCurve) curvePiece(const Handle(Geom_BSplineCurve) & curve, double from, double to) {
  Handle(Geom_BSplineCurve) piece = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  piece->Segment(std::min(from, to), std::max(from, to));
  if (from > to) piece->Reverse();
  return piece;
}

NacelleProfile NacelleProfile::named(const Configuration& configuration, const std::string& uid, bool curveProfile,
                                     const std::string& where) {
  const schema::ProfileGeometry2DType* definition = findProfile(configuration, uid, curveProfile);
  if (definition == nullptr)
    throw Error(ErrorCode::InvalidModel,
                "'" + uid + "' names no " + (curveProfile ? "curve profile" : "nacelle profile"), {}, where);
  if (definition->cst2D) return fromCst(*definition->cst2D, definition->xpath + "/cst2D");
  if (!definition->pointList)
    throw Error(ErrorCode::InvalidModel, "the profile has neither a point list nor a cst2D definition", {},
                definition->xpath);
  const std::string listPath = definition->xpath + "/pointList";
  const std::vector<double> x = model::parseVector(definition->pointList->x, listPath + "/x"),
                            y = model::parseVector(definition->pointList->y, listPath + "/y");
  if (x.size() != y.size() || x.size() < 2)
    throw Error(ErrorCode::InvalidModel, "x and y need the same number of values, at least two", {}, listPath);
  std::vector<gp_Pnt> points;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (points.empty() || points.back().Distance(gp_Pnt(x[i], 0.0, y[i])) > kJoinTolerance)
      points.emplace_back(x[i], 0.0, y[i]);
  if (points.size() < 2)
    throw Error(ErrorCode::InvalidModel, "the profile has fewer than two distinct points", {}, listPath);
  const std::vector<double> parameters = geometry::chordParameters(points, 0.5);
  NacelleProfile profile;
  profile.whole_ = geometry::interpolateCurve(points, parameters, 3);
  if (curveProfile) return profile;
  // The leading edge: the point farthest from the middle of the trailing edge.
  const gp_Pnt middle((points.front().XYZ() + points.back().XYZ()) / 2.0);
  std::size_t leadingEdge = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i].Distance(middle) > points[leadingEdge].Distance(middle)) leadingEdge = i;
  if (leadingEdge == 0 || leadingEdge + 1 == points.size())
    throw Error(ErrorCode::InvalidModel, "the profile's leading edge is one of its ends", {}, listPath);
  profile.lower_ = curvePiece(profile.whole_, parameters.front(), parameters[leadingEdge]);
  profile.upper_ = curvePiece(profile.whole_, parameters[leadingEdge], parameters.back());
  if (points.front().Distance(points.back()) > kJoinTolerance)
    profile.trailingEdge_ = std::make_pair(points.back(), points.front());
  return profile;
}

NacelleProfile NacelleProfile::fromCst(const schema::Cst2DType& cst, const std::string& xpath) {
  NacelleProfile profile;
  cstSides(cst, xpath, profile.lower_, profile.upper_);
  profile.whole_ = joined(profile.lower_, profile.upper_);
  const gp_Pnt first = profile.lower_->StartPoint(), last = profile.upper_->EndPoint();
  if (first.Distance(last) > kJoinTolerance) profile.trailingEdge_ = std::make_pair(last, first);
  return profile;
}

}  // namespace airshape::nacelle
