#include "fuselage_guide_curves.h"

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>

#include "airshape/error.h"

namespace airshape::fuselage {

namespace {

/// Where a share `rc` of a profile's length lies (with its closing edge when it is open):
/// on the curve (with its parameter) or, beyond the curve, on the closing edge or the
/// extension of an end tangent.
struct ProfilePosition {
  gp_Pnt point;
  std::optional<double> parameter;
};

ProfilePosition positionAtRelativeCircumference(const PlacedProfile& section, double rc) {
  const Geom_BSplineCurve& curve = *section.curve;
  GeomAdaptor_Curve adaptor(section.curve);
  const double curveLength = GCPnts_AbscissaPoint::Length(adaptor);
  const gp_Pnt start = curve.StartPoint(), end = curve.EndPoint();
  const bool closingEdgeCounts = !section.profile->closed && !section.profile->mirroredHalf;
  const double closingLength = closingEdgeCounts ? start.Distance(end) : 0.0;
  const double length = rc * (curveLength + closingLength);
  if (length < 0.0) return {start.Translated(curve.DN(curve.FirstParameter(), 1).Normalized() * length), {}};
  if (length <= curveLength * (1.0 + 1e-12)) {  // rc = 1 on a closed profile is its end
    if (length >= curveLength) return {end, curve.LastParameter()};
    const double t = GCPnts_AbscissaPoint(adaptor, length, curve.FirstParameter()).Parameter();
    return {curve.Value(t), t};
  }
  if (closingLength == 0.0)
    return {end.Translated(curve.DN(curve.LastParameter(), 1).Normalized() * (length - curveLength)), {}};
  return {end.Translated(gp_Vec(end, start).Normalized() * (length - curveLength)), {}};
}

/// Where a guide meets a profile: by relative circumference, or directly by the profile
/// curve's parameter (the reference's fromParameter/toParameter).
ProfilePosition positionOn(const PlacedProfile& section, const model::ProfilePosition& at) {
  if (!at.isCurveParameter) return positionAtRelativeCircumference(section, at.value);
  const Geom_BSplineCurve& curve = *section.curve;
  if (at.value < curve.FirstParameter() || at.value > curve.LastParameter())
    throw Error(ErrorCode::InvalidModel, "a guide curve's profile parameter lies outside the profile's range");
  return {curve.Value(at.value), at.value};
}

}  // namespace

FuselageGuides fuselageGuideCurves(const schema::CpacsType& cpacs, const std::vector<PlacedProfile>& sections,
                                   const std::vector<const schema::GuideCurvesType*>& perSegment) {
  model::GuideCurveSections described;
  described.count = sections.size();
  described.pointAt = [&](std::size_t k, const model::ProfilePosition& at) {
    return positionOn(sections[k], at).point;
  };
  described.scale = [&](std::size_t k) { return sections[k].profile->guideScale(sections[k].transform); };
  described.centre = [&](std::size_t k) {
    const Eigen::Vector3d origin = sections[k].transform.translation();
    return gp_Pnt(origin.x(), origin.y(), origin.z());
  };
  described.defaultXDirection = gp_Vec(0, 0, 1);  // global z, as the reference has it
  FuselageGuides guides;
  const std::vector<model::GuideCurve> built = model::buildGuideCurves(cpacs, perSegment, described);
  const auto K = static_cast<Eigen::Index>(sections.size()), L = static_cast<Eigen::Index>(built.size());
  guides.crossings.profileParameters.resize(K, L);
  guides.crossings.guideParameters.resize(K, L);
  for (Eigen::Index l = 0; l < L; ++l) {
    const model::GuideCurve& guide = built[static_cast<std::size_t>(l)];
    guides.curves.push_back(guide.curve);
    guides.startPositions.push_back(guide.positions.front().value);
    guides.smoothAt.push_back(guide.smoothAt);
    for (Eigen::Index k = 0; k < K; ++k) {
      const auto position =
          positionOn(sections[static_cast<std::size_t>(k)], guide.positions[static_cast<std::size_t>(k)]);
      if (!position.parameter)
        throw Error(ErrorCode::InvalidModel, "guide curve '" + guide.rootUid +
                                                 "' leaves the profile's curve (relative circumference beyond it)");
      guides.crossings.profileParameters(k, l) = *position.parameter;
      guides.crossings.guideParameters(k, l) = guide.sectionParameters[static_cast<std::size_t>(k)];
    }
  }
  return guides;
}

}  // namespace airshape::fuselage
