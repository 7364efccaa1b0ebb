#include "cowl_guides.h"

#include <cmath>
#include <map>
#include <string>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/model/placement.h"

namespace airshape::nacelle {

namespace {

constexpr double kGuideRadiansPerDegree = M_PI / 180.0;
/// Points sampled on each sector of a guide (enough for the chevrons of a guide curve profile).
constexpr int kSectorSamples = 32;
constexpr double kSameZeta = 1e-9;
/// Offsets of a guide curve profile below this count as none.
constexpr double kNoOffset = 1e-12;

/// A guide's offsets from its cubic step over the share u of a sector: (rY, rZ) interpolated
/// over rX, zero at both ends.
class GuideOffsets {
 public:
  static GuideOffsets none() { return GuideOffsets(); }

  static GuideOffsets named(const Configuration& configuration, const std::string& uid, const std::string& where) {
    const auto& vehicles = configuration.cpacs().vehicles;
    const schema::GuideCurveProfileGeometryType* profile = nullptr;
    if (vehicles && vehicles->profiles && vehicles->profiles->guideCurves)
      for (const auto& candidate : vehicles->profiles->guideCurves->guideCurveProfile)
        if (candidate.uID == uid && profile == nullptr) profile = &candidate;
    if (profile == nullptr || !profile->pointList)
      throw Error(ErrorCode::InvalidModel, "'" + uid + "' names no guide curve profile with a point list", {}, where);
    const std::string list = profile->xpath + "/pointList";
    const std::vector<double> rx = model::parseVector(profile->pointList->rX, list + "/rX"),
                              ry = model::parseVector(profile->pointList->rY, list + "/rY"),
                              rz = model::parseVector(profile->pointList->rZ, list + "/rZ");
    if (rx.size() != ry.size() || rx.size() != rz.size())
      throw Error(ErrorCode::InvalidModel, "rX, rY and rZ need the same number of values", {}, list);
    std::vector<gp_Pnt> points{gp_Pnt(0, 0, 0)};
    std::vector<double> shares{0.0};
    for (std::size_t i = 0; i < rx.size(); ++i) {
      const bool atSection = rx[i] == 0.0 || rx[i] == 1.0;
      if (atSection && (std::abs(ry[i]) > kNoOffset || std::abs(rz[i]) > kNoOffset))
        throw Error(ErrorCode::InvalidModel, "a guide must meet the sections: no offset at rX = 0 or 1", {}, list);
      if (atSection) continue;  // the ends are the sections' points themselves
      if (rx[i] <= shares.back() || rx[i] > 1.0)
        throw Error(ErrorCode::InvalidModel, "rX must rise strictly within [0, 1]", {}, list + "/rX");
      points.emplace_back(rx[i], ry[i], rz[i]);
      shares.push_back(rx[i]);
    }
    points.emplace_back(1, 0, 0);
    shares.push_back(1.0);
    GuideOffsets offsets;
    offsets.curve_ = geometry::interpolateCurve(points, shares, 3);
    return offsets;
  }

  /// (axial, radial) offsets at share u, before scaling.
  std::pair<double, double> at(double u) const {
    if (curve_.IsNull()) return {0.0, 0.0};
    const gp_Pnt p = curve_->Value(u);
    return {p.Y(), p.Z()};
  }

 private:
  Handle(Geom_BSplineCurve) curve_;
};

/// One sector of a guide: from a section's point at `fromZeta` to the next section's at `toZeta`.
struct GuideSector {
  double fromZeta, toZeta;
  GuideOffsets offsets;
};

/// The CPACS guide curve of that zeta starting at a section, if any.
const schema::NacelleGuideCurveType* cpacsGuide(const schema::NacelleCowlType& cowl, double zeta,
                                                const std::string& sectionUID) {
  if (!cowl.guideCurves) return nullptr;
  for (const auto& guide : cowl.guideCurves->nacelleGuideCurve)
    if (std::abs(guide.fromZeta - zeta) < kSameZeta && guide.startSectionUID == sectionUID) return &guide;
  return nullptr;
}

/// Appends the samples of one sector (without its end point) with parameters by angle.
void sampleSector(const PlacedProfile& a, const PlacedProfile& b, double angleA, double angleB,
                  const GuideSector& sector, std::vector<gp_Pnt>& points, std::vector<double>& parameters) {
  const gp_Pnt start = a.at(sector.fromZeta), end = b.at(sector.toZeta);
  const double startR = std::hypot(start.Y(), start.Z()), endR = std::hypot(end.Y(), end.Z());
  const double chordA = a.chord(), chordB = b.chord();
  for (int j = 0; j < kSectorSamples; ++j) {
    const double u = static_cast<double>(j) / kSectorSamples, step = u * u * (3.0 - 2.0 * u);
    const auto [axialOffset, radialOffset] = sector.offsets.at(u);
    const double x = start.X() + step * (end.X() - start.X()) + ((1 - u) * chordA + u * chordB) * axialOffset;
    const double r = startR + step * (endR - startR) + ((1 - u) * a.radius + u * b.radius) * radialOffset;
    const double angle = angleA + u * (angleB - angleA);
    points.emplace_back(x, -r * std::sin(angle * kGuideRadiansPerDegree), r * std::cos(angle * kGuideRadiansPerDegree));
    parameters.push_back(angle / 360.0);
  }
}

/// The closed guide through the sectors (sector k from section k to k + 1, the last back to the first).
Handle(Geom_BSplineCurve)
    closedGuide(const std::vector<PlacedProfile>& sections, const std::vector<GuideSector>& sectors) {
  std::vector<gp_Pnt> points;
  std::vector<double> parameters;
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const std::size_t next = (k + 1) % sections.size();
    const double angleB = next == 0 ? sections[0].angle + 360.0 : sections[next].angle;
    sampleSector(sections[k], sections[next], sections[k].angle, angleB, sectors[k], points, parameters);
  }
  points.push_back(points.front());
  parameters.push_back(parameters.front() + 1.0);
  return geometry::interpolateCurve(points, parameters, 3, true);
}

/// The offsets of the guide curve profiles a cowl's guides use, each read once. An unreadable
/// profile is warned about once and its guides follow the plain step (the rest of the cowl is
/// still built as the file means it).
class GuideProfiles {
 public:
  explicit GuideProfiles(const Configuration& configuration) : configuration_(configuration) {}

  const GuideOffsets& of(const schema::NacelleGuideCurveType& guide) {
    const std::string& uid = guide.guideCurveProfileUID;
    auto known = read_.find(uid);
    if (known != read_.end()) return known->second;
    GuideOffsets offsets = GuideOffsets::none();
    try {
      offsets = GuideOffsets::named(configuration_, uid, guide.xpath + "/guideCurveProfileUID");
    } catch (const Error& error) {
      configuration_.warnAboutGeometry(
          {Problem::Severity::Warning, error.cpacsPath(),
           error.message() + "; the guides using profile '" + uid + "' are built without its offsets"});
    }
    return read_.emplace(uid, offsets).first->second;
  }

 private:
  const Configuration& configuration_;
  std::map<std::string, GuideOffsets> read_;
};

/// The sectors of the guide at `zeta`: the cowl's own guide curves where given, the plain step
/// elsewhere. Each sector must end at the zeta where the next one starts.
std::vector<GuideSector> guideSectors(GuideProfiles& profiles, const schema::NacelleCowlType& cowl,
                                      const std::vector<PlacedProfile>& sections, double zeta) {
  std::vector<GuideSector> sectors;
  for (const PlacedProfile& section : sections) {
    const schema::NacelleGuideCurveType* guide = cpacsGuide(cowl, zeta, section.uID);
    if (guide == nullptr) {
      sectors.push_back({zeta, zeta, GuideOffsets::none()});
      continue;
    }
    if (std::abs(guide->toZeta - zeta) > kSameZeta)
      throw Error(ErrorCode::NotImplemented,
                  "a guide curve from one zeta to another (" + std::to_string(guide->fromZeta) + " to " +
                      std::to_string(guide->toZeta) + ") is not built yet",
                  {}, guide->xpath);
    sectors.push_back({zeta, zeta, profiles.of(*guide)});
  }
  return sectors;
}

}  // namespace

std::vector<CowlGuide> cowlGuides(const Configuration& configuration, const schema::NacelleCowlType& cowl,
                                  const std::vector<PlacedProfile>& sections,
                                  const std::vector<double>& requiredZetas) {
  std::vector<double> zetas = requiredZetas;
  if (cowl.guideCurves)
    for (const auto& guide : cowl.guideCurves->nacelleGuideCurve) {
      if (guide.fromZeta < -1.0 || guide.fromZeta > 1.0)
        throw Error(ErrorCode::InvalidModel, "fromZeta is outside [-1, 1]", {}, guide.xpath + "/fromZeta");
      bool known = false;
      for (double zeta : zetas) known = known || std::abs(zeta - guide.fromZeta) < kSameZeta;
      if (!known) zetas.push_back(guide.fromZeta);
    }
  GuideProfiles profiles(configuration);
  std::vector<CowlGuide> guides;
  for (double zeta : zetas)
    guides.push_back({zeta, closedGuide(sections, guideSectors(profiles, cowl, sections, zeta))});
  return guides;
}

}  // namespace airshape::nacelle
