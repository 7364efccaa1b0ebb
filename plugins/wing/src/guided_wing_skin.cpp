#include "guided_wing_skin.h"

#include <algorithm>
#include <map>

#include <BSplCLib.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <TColStd_Array1OfReal.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/gordon_surface.h"
#include "airshape/model/guide_curves.h"
#include "wing_geometry.h"

namespace airshape::wing {

namespace {

/// Linear between neighbouring airfoils, as the reference's guided wing skins are: the
/// guides shape the skin, the airfoils are joined without overshoot (see docs/wing.md).
constexpr int kDegreeAcrossProfiles = 1;

/// A placed airfoil as one curve: lower side reversed over [0, 1], upper side over [1, 2].
Handle(Geom_BSplineCurve) wholeAirfoil(const SegmentEnd& end) {
  Handle(Geom_BSplineCurve) lower = geometry::transformed(end.profile->lowerCurve(), end.transform);
  lower->Reverse();
  Handle(Geom_BSplineCurve) upper = geometry::transformed(end.profile->upperCurve(), end.transform);
  TColStd_Array1OfReal knots(1, upper->NbKnots());
  upper->Knots(knots);
  BSplCLib::Reparametrize(1.0, 2.0, knots);
  upper->SetKnots(knots);
  return geometry::concatenateCurves({lower, upper});
}

/// The parameter on a whole airfoil at relative circumference rc (−1 lower TE end, 0 LE,
/// +1 upper TE end), each side measured by its own length.
double parameterAtRelativeCircumference(const Handle(Geom_BSplineCurve) & airfoil, double rc) {
  if (rc < -1.0 - 1e-9 || rc > 1.0 + 1e-9)
    throw Error(ErrorCode::InvalidModel, "a wing guide curve's relative circumference lies outside [-1, 1]");
  GeomAdaptor_Curve curve(airfoil);
  const double from = rc <= 0.0 ? 0.0 : 1.0, to = rc <= 0.0 ? 1.0 : 2.0;
  const double side = GCPnts_AbscissaPoint::Length(curve, from, to);
  const double along = (rc <= 0.0 ? rc + 1.0 : rc) * side;
  if (along <= 0.0) return from;
  if (along >= side) return to;
  return GCPnts_AbscissaPoint(curve, along, from).Parameter();
}

/// A curve through the airfoils' points at whole-airfoil parameter `at`, passing airfoil k
/// at parameter sections[k]: a stand-in guide along a trailing-edge end.
Handle(Geom_BSplineCurve) interpolateThrough(const std::vector<Handle(Geom_BSplineCurve)>& airfoils, double at,
                                             const std::vector<double>& sections) {
  std::vector<gp_Pnt> points;
  for (const auto& airfoil : airfoils) points.push_back(airfoil->Value(at));
  return geometry::interpolateCurve(points, sections, 3);
}

/// The whole-airfoil parameter where a guide meets it; the reference's fromParameter and
/// toParameter have no defined meaning on wings.
double parameterAt(const Handle(Geom_BSplineCurve) & airfoil, const model::ProfilePosition& at) {
  if (at.isCurveParameter)
    throw Error(ErrorCode::InvalidModel,
                "wing guide curves need relative circumferences (fromParameter and "
                "toParameter are not defined for wings)");
  return parameterAtRelativeCircumference(airfoil, at.value);
}

/// The <guideCurves> of each segment (chain order; null where it has none).
std::vector<const schema::GuideCurvesType*> guideCurvesPerSegment(const schema::WingType& wing,
                                                                  const std::vector<WingSegment>& segments) {
  std::map<std::string, const schema::WingSegmentType*> definitions;
  if (wing.segments)
    for (const auto& definition : wing.segments->segment) definitions[definition.uID] = &definition;
  std::vector<const schema::GuideCurvesType*> perSegment;
  for (const WingSegment& segment : segments) {
    const auto* definition = definitions.at(segment.uid);
    perSegment.push_back(definition->guideCurves ? &*definition->guideCurves : nullptr);
  }
  return perSegment;
}

/// A guide with where it crosses every airfoil: whole-airfoil parameters and its own.
struct GuideCrossing {
  Handle(Geom_BSplineCurve) curve;
  std::vector<double> airfoilParameters, guideParameters;
};

/// The wing's guides, completed so that the skin reaches both trailing-edge ends (on a
/// sharp trailing edge one guide there serves both; a missing one runs through the
/// airfoils' ends), in the order they cross the airfoils.
std::vector<GuideCrossing> crossingGuides(const std::vector<model::GuideCurve>& guides,
                                          const std::vector<Handle(Geom_BSplineCurve)>& airfoils, bool blunt) {
  std::vector<GuideCrossing> result;
  for (const model::GuideCurve& guide : guides) {
    GuideCrossing crossing{guide.curve, {}, guide.sectionParameters};
    for (std::size_t k = 0; k < airfoils.size(); ++k)
      crossing.airfoilParameters.push_back(parameterAt(airfoils[k], guide.positions[k]));
    result.push_back(crossing);
  }
  const std::vector<double> sectionParameters = result.front().guideParameters;
  auto guideAt = [&](double end) -> const GuideCrossing* {
    for (const GuideCrossing& c : result)
      if (std::abs(c.airfoilParameters.front() - end) < 1e-9) return &c;
    return nullptr;
  };
  for (double end : {0.0, 2.0}) {
    if (guideAt(end)) continue;
    const GuideCrossing* other = blunt ? nullptr : guideAt(2.0 - end);
    result.push_back({other ? other->curve : interpolateThrough(airfoils, end, sectionParameters),
                      std::vector<double>(airfoils.size(), end), sectionParameters});
  }
  std::sort(result.begin(), result.end(), [](const GuideCrossing& a, const GuideCrossing& b) {
    return a.airfoilParameters.front() < b.airfoilParameters.front();
  });
  return result;
}

/// What the guide-curve builder needs of the wing's sections (CONVENTIONS §9.1): points by
/// relative circumference on the whole airfoils, the global chord as scale, chord midpoints
/// as centres, the wing's x axis as the default rXDirection.
model::GuideCurveSections describeSections(const Configuration& configuration, const schema::WingType& wing,
                                           const std::vector<const SegmentEnd*>& sections,
                                           const std::vector<Handle(Geom_BSplineCurve)>& airfoils) {
  model::GuideCurveSections described;
  described.count = sections.size();
  described.pointAt = [&airfoils](std::size_t k, const model::ProfilePosition& at) {
    return airfoils[k]->Value(parameterAt(airfoils[k], at));
  };
  described.scale = [sections](std::size_t k) {
    return sections[k]->leadingEdge().Distance(sections[k]->trailingEdge());
  };
  described.centre = [sections](std::size_t k) {
    return gp_Pnt(0.5 * (sections[k]->leadingEdge().XYZ() + sections[k]->trailingEdge().XYZ()));
  };
  const Eigen::Vector3d x = model::componentTransform(configuration, wing.uID).linear() * Eigen::Vector3d::UnitX();
  described.defaultXDirection = gp_Vec(x.x(), x.y(), x.z());
  return described;
}

}  // namespace

std::shared_ptr<const GuidedWingSkin> GuidedWingSkin::build(const Configuration& configuration,
                                                            const schema::WingType& wing,
                                                            const std::vector<WingSegment>& segments) {
  const std::vector<const schema::GuideCurvesType*> perSegment = guideCurvesPerSegment(wing, segments);
  if (!model::hasGuideCurves(perSegment)) return nullptr;

  auto skin = std::make_shared<GuidedWingSkin>();
  std::vector<const SegmentEnd*> sections;
  for (const WingSegment& segment : segments) sections.push_back(&segment.inner);
  sections.push_back(&segments.back().outer);
  for (const SegmentEnd* end : sections) skin->airfoils_.push_back(wholeAirfoil(*end));
  skin->blunt_ = sections.front()->profile->bluntTrailingEdge();

  const std::vector<GuideCrossing> guides =
      crossingGuides(model::buildGuideCurves(configuration.cpacs(), perSegment,
                                             describeSections(configuration, wing, sections, skin->airfoils_)),
                     skin->airfoils_, skin->blunt_);
  std::vector<Handle(Geom_BSplineCurve)> guideCurves;
  geometry::KnownCrossings crossings;
  const auto K = static_cast<Eigen::Index>(sections.size()), L = static_cast<Eigen::Index>(guides.size());
  crossings.profileParameters.resize(K, L);
  crossings.guideParameters.resize(K, L);
  skin->crossingParameters_.assign(sections.size(), {});
  for (Eigen::Index l = 0; l < L; ++l) {
    const GuideCrossing& guide = guides[static_cast<std::size_t>(l)];
    guideCurves.push_back(guide.curve);
    for (Eigen::Index k = 0; k < K; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      crossings.profileParameters(k, l) = guide.airfoilParameters[kk];
      crossings.guideParameters(k, l) = guide.guideParameters[kk];
      skin->crossingParameters_[kk].push_back(guide.airfoilParameters[kk]);
    }
  }
  const geometry::GordonSurface gordon =
      geometry::buildGordonSurface(skin->airfoils_, guideCurves, {}, &crossings, kDegreeAcrossProfiles);
  if (gordon.profileSites.size() != skin->airfoils_.size() || gordon.guideSites.size() != guideCurves.size())
    throw Error(ErrorCode::InvalidModel, "the guide curves do not cross every airfoil of wing '" + wing.uID + "' once");
  skin->surface_ = gordon.surface;
  skin->sectionSites_ = gordon.profileSites;
  skin->guideSites_ = gordon.guideSites;
  return skin;
}

double GuidedWingSkin::uAt(std::size_t section, double wholeParameter) const {
  // Linear between the guides: the parameter the airfoil has at each guide is the u the
  // guide runs at on the skin.
  const std::vector<double>& at = crossingParameters_[section];
  std::size_t l = 1;
  while (l + 1 < at.size() && wholeParameter > at[l]) ++l;
  const double share = (wholeParameter - at[l - 1]) / (at[l] - at[l - 1]);
  return guideSites_[l - 1] + share * (guideSites_[l] - guideSites_[l - 1]);
}

gp_Pnt GuidedWingSkin::pointAt(std::size_t segment, double eta, double wholeParameter) const {
  const double u = (1.0 - eta) * uAt(segment, wholeParameter) + eta * uAt(segment + 1, wholeParameter);
  const double v = (1.0 - eta) * sectionSites_[segment] + eta * sectionSites_[segment + 1];
  return surface_->Value(u, v);
}

gp_Pnt GuidedWingSkin::upperPoint(std::size_t segment, double eta, double xsi) const {
  return pointAt(segment, eta, 1.0 + xsi);
}

gp_Pnt GuidedWingSkin::lowerPoint(std::size_t segment, double eta, double xsi) const {
  return pointAt(segment, eta, 1.0 - xsi);
}

geometry::LoftPiece GuidedWingSkin::segmentPiece(std::size_t segment) const {
  return geometry::loftPiece(surface_, sectionSites_[segment], sectionSites_[segment + 1], !blunt_);
}

}  // namespace airshape::wing
