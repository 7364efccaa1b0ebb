#include "fuselage_guide_curves.h"

#include <map>

#include "airshape/error.h"
#include "airshape/geometry/arc_length.h"

namespace airshape::fuselage {

namespace {

/// Where a share `rc` of a profile's length lies (with its closing edge when it is open):
/// on the curve (with its parameter) or, beyond the curve, on the closing edge or the
/// extension of an end tangent.
struct ProfilePosition {
  gp_Pnt point;
  std::optional<double> parameter;
};

/// Finds positions by relative circumference on one placed profile. Many guides meet each
/// profile and every one is asked for more than once, so the lengths up to the profile's
/// knots are measured once (geometry::ArcLength) and each answer is kept: arc lengths were
/// two thirds of the cost of building a guided fuselage.
class CircumferenceWalker {
 public:
  explicit CircumferenceWalker(const PlacedProfile& section)
      : curve_(*section.curve),
        arc_(section.curve),
        curveLength_(arc_.total()),
        closingLength_(!section.profile->closed && !section.profile->mirroredHalf
                           ? curve_.StartPoint().Distance(curve_.EndPoint())
                           : 0.0) {}

  ProfilePosition at(double rc) {
    const auto cached = positions_.find(rc);
    if (cached != positions_.end()) return cached->second;
    return positions_.emplace(rc, measured(rc * (curveLength_ + closingLength_))).first->second;
  }

 private:
  ProfilePosition measured(double length) const {
    const gp_Pnt start = curve_.StartPoint(), end = curve_.EndPoint();
    if (length < 0.0) return {start.Translated(curve_.DN(curve_.FirstParameter(), 1).Normalized() * length), {}};
    if (length <= curveLength_ * (1.0 + 1e-12)) {  // rc = 1 on a closed profile is its end
      if (length >= curveLength_) return {end, curve_.LastParameter()};
      const double t = arc_.parameterAt(length);
      return {curve_.Value(t), t};
    }
    if (closingLength_ == 0.0)
      return {end.Translated(curve_.DN(curve_.LastParameter(), 1).Normalized() * (length - curveLength_)), {}};
    return {end.Translated(gp_Vec(end, start).Normalized() * (length - curveLength_)), {}};
  }

  const Geom_BSplineCurve& curve_;
  geometry::ArcLength arc_;
  double curveLength_, closingLength_;
  std::map<double, ProfilePosition> positions_;
};

/// Where a guide meets a profile: by relative circumference, or directly by the profile
/// curve's parameter (the reference's fromParameter/toParameter).
ProfilePosition positionOn(const PlacedProfile& section, CircumferenceWalker& walker,
                           const model::ProfilePosition& at) {
  if (!at.isCurveParameter) return walker.at(at.value);
  const Geom_BSplineCurve& curve = *section.curve;
  if (at.value < curve.FirstParameter() || at.value > curve.LastParameter())
    throw Error(ErrorCode::InvalidModel, "a guide curve's profile parameter lies outside the profile's range");
  return {curve.Value(at.value), at.value};
}

}  // namespace

FuselageGuides fuselageGuideCurves(const schema::CpacsType& cpacs, const std::vector<PlacedProfile>& sections,
                                   const std::vector<const schema::GuideCurvesType*>& perSegment) {
  std::vector<CircumferenceWalker> walkers(sections.begin(), sections.end());
  model::GuideCurveSections described;
  described.count = sections.size();
  described.pointAt = [&](std::size_t k, const model::ProfilePosition& at) {
    return positionOn(sections[k], walkers[k], at).point;
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
    guides.uids.push_back(guide.rootUid);
    guides.startPositions.push_back(guide.positions.front().value);
    guides.smoothAt.push_back(guide.smoothAt);
    for (Eigen::Index k = 0; k < K; ++k) {
      const auto section = static_cast<std::size_t>(k);
      const auto position = positionOn(sections[section], walkers[section], guide.positions[section]);
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
