#include "guided_wing_skin.h"

#include <algorithm>
#include <map>

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/coons_patches.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/model/guide_curves.h"
#include "wing_geometry.h"

namespace airshape::wing {

namespace {

/// A placed airfoil as one curve: lower side reversed over [0, 1], upper side over [1, 2].
Handle(Geom_BSplineCurve) wholeAirfoil(const SegmentEnd& end) {
  Handle(Geom_BSplineCurve) lower = geometry::transformed(end.profile->lowerCurve(), end.transform);
  lower->Reverse();
  Handle(Geom_BSplineCurve) upper = geometry::transformed(end.profile->upperCurve(), end.transform);
  geometry::setParameterRange(*upper, 1.0, 2.0);
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

/// A guide with where it crosses every airfoil (whole-airfoil parameters and its own) and
/// its relative circumference at the root.
struct GuideCrossing {
  Handle(Geom_BSplineCurve) curve;
  std::vector<double> airfoilParameters, guideParameters;
  double relativeCircumference = 0.0;
  std::vector<bool> smoothAt;  ///< per section: counted as C2 there (model::GuideCurve::smoothAt)
  std::string name;            ///< for errors: "guide curve 'uID'" or what stands in for one
};

/// The wing's guides, completed so that the skin reaches both trailing-edge ends (on a
/// sharp trailing edge one guide there serves both; a missing one runs through the
/// airfoils' ends), in the order they cross the airfoils.
std::vector<GuideCrossing> crossingGuides(const std::vector<model::GuideCurve>& guides,
                                          const std::vector<Handle(Geom_BSplineCurve)>& airfoils, bool blunt) {
  std::vector<GuideCrossing> result;
  for (const model::GuideCurve& guide : guides) {
    GuideCrossing crossing{
        guide.curve, {}, guide.sectionParameters, 0.0, guide.smoothAt, "guide curve '" + guide.rootUid + "'"};
    for (std::size_t k = 0; k < airfoils.size(); ++k)
      crossing.airfoilParameters.push_back(parameterAt(airfoils[k], guide.positions[k]));
    // The root's relative circumference; a guide at a trailing-edge end (|rc| = 1, on a sharp
    // trailing edge possibly placed at the other end) counts by the end it was placed at.
    const double rc = guide.positions.front().value;
    crossing.relativeCircumference = std::abs(rc) < 1.0 ? rc : crossing.airfoilParameters.front() - 1.0;
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
    result.push_back(
        {other ? other->curve : interpolateThrough(airfoils, end, sectionParameters),
         std::vector<double>(airfoils.size(), end), sectionParameters, end - 1.0,
         other ? other->smoothAt : std::vector<bool>(airfoils.size(), false),
         other ? other->name : std::string("the trailing edge's ") + (end == 0.0 ? "lower" : "upper") + " end"});
  }
  std::sort(result.begin(), result.end(), [](const GuideCrossing& a, const GuideCrossing& b) {
    return a.airfoilParameters.front() < b.airfoilParameters.front();
  });
  return result;
}

/// Whether the cell of segment k between guides l and l+1 is blended round, as the
/// reference decides it: when a curve runs smoothly (C2) through one of its corners, that
/// is a guide counted as smooth through a section (GuideCurve::smoothAt), or an airfoil through a
/// guide away from its leading edge (where the reference's airfoil is only C1, joined from
/// two sides) and trailing edge; otherwise bilinearly.
bool roundedCell(const std::vector<GuideCrossing>& guides, std::size_t k, std::size_t l) {
  for (const GuideCrossing* guide : {&guides[l], &guides[l + 1]}) {
    if (guide->smoothAt[k] || guide->smoothAt[k + 1]) return true;
    const double rc = std::abs(guide->relativeCircumference);
    if (rc > 1e-3 && rc < 1.0 - 1e-3) return true;
  }
  return false;
}

/// The length that scales a guide's rX and rZ at a section, as the reference measures it:
/// the airfoil's chord (TE − LE in the airfoil's x-z plane) laid into 3-D with its x and z
/// swapped, then placed. The reference builds its chord line in a plane whose first axis is
/// z, so this is the global chord length only where the section scales x and z alike (the
/// usual case); where it does not, z's scaling counts (docs/wing.md).
double guideScale(const SegmentEnd& section) {
  const gp_Pnt le = section.profile->leadingEdge(), te = section.profile->trailingEdge();
  const Eigen::Vector3d chordAsLaid(te.Z() - le.Z(), 0.0, te.X() - le.X());
  return (section.transform.linear() * chordAsLaid).norm();
}

/// What the guide-curve builder needs of the wing's sections (CONVENTIONS §9.1): points by
/// relative circumference on the whole airfoils, guideScale as scale, the leading edges as
/// centres (the reference means chord midpoints, but its midpoint computation leaves the
/// leading edge in place, and the guides' parameters follow from these points), the wing's
/// x axis as the default rXDirection.
model::GuideCurveSections describeSections(const Configuration& configuration, const schema::WingType& wing,
                                           const std::vector<const SegmentEnd*>& sections,
                                           const std::vector<Handle(Geom_BSplineCurve)>& airfoils) {
  model::GuideCurveSections described;
  described.count = sections.size();
  described.pointAt = [&airfoils](std::size_t k, const model::ProfilePosition& at) {
    return airfoils[k]->Value(parameterAt(airfoils[k], at));
  };
  described.scale = [sections](std::size_t k) { return guideScale(*sections[k]); };
  described.centre = [sections](std::size_t k) { return sections[k]->leadingEdge(); };
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
  for (Eigen::Index l = 0; l < L; ++l) {
    const GuideCrossing& guide = guides[static_cast<std::size_t>(l)];
    guideCurves.push_back(guide.curve);
    skin->relativeCircumferences_.push_back(guide.relativeCircumference);
    for (Eigen::Index k = 0; k < K; ++k) {
      crossings.profileParameters(k, l) = guide.airfoilParameters[static_cast<std::size_t>(k)];
      crossings.guideParameters(k, l) = guide.guideParameters[static_cast<std::size_t>(k)];
    }
  }
  try {
    skin->rows_ = geometry::buildCoonsPatchRows(
        skin->airfoils_, guideCurves, crossings,
        [&](std::size_t k, std::size_t l) {
          return roundedCell(guides, k, l) ? geometry::PatchBlending::Rounded : geometry::PatchBlending::Bilinear;
        },
        [&](std::size_t k, std::size_t l) {
          return "the cell between the airfoils of elements '" + sections[k]->elementUid + "' and '" +
                 sections[k + 1]->elementUid + "' and between " + guides[l].name + " and " + guides[l + 1].name;
        });
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), "the guided skin: " + error.message(), {}, wing.xpath + "/segments");
  }
  return skin;
}

gp_Pnt GuidedWingSkin::pointAt(std::size_t segment, double eta, double relativeCircumference) const {
  // Cell l lies between the guides at relative circumferences rc_l and rc_l+1, over u in
  // [l, l+1]; xsi (as rc) maps linearly onto it, as in the reference.
  const std::vector<double>& rc = relativeCircumferences_;
  std::size_t l = 0;
  while (l + 2 < rc.size() && relativeCircumference > rc[l + 1]) ++l;
  const double share = (relativeCircumference - rc[l]) / (rc[l + 1] - rc[l]);
  return rows_[segment]->Value(static_cast<double>(l) + std::clamp(share, 0.0, 1.0), eta);
}

gp_Pnt GuidedWingSkin::upperPoint(std::size_t segment, double eta, double xsi) const {
  return pointAt(segment, eta, xsi);
}

gp_Pnt GuidedWingSkin::lowerPoint(std::size_t segment, double eta, double xsi) const {
  return pointAt(segment, eta, -xsi);
}

double GuidedWingSkin::leadingEdgeU() const {
  for (std::size_t l = 0; l < relativeCircumferences_.size(); ++l)
    if (std::abs(relativeCircumferences_[l]) < 1e-3) return static_cast<double>(l);
  return 0.0;
}

}  // namespace airshape::wing
