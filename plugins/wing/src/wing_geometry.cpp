#include "wing_geometry.h"

#include <unordered_map>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/placed_elements.h"
#include "airshape/model/segment_chain.h"

namespace airshape::wing {

namespace {

gp_Pnt lerp(const gp_Pnt& a, const gp_Pnt& b, double share) {
  return gp_Pnt((1.0 - share) * a.XYZ() + share * b.XYZ());
}

/// The wing airfoils of the document by uID, built on demand.
class AirfoilLibrary {
 public:
  explicit AirfoilLibrary(const Configuration& configuration) : configuration_(configuration) {
    const schema::CpacsType& cpacs = configuration.cpacs();
    if (!cpacs.vehicles || !cpacs.vehicles->profiles) return;
    const schema::ProfilesType& profiles = *cpacs.vehicles->profiles;
    if (profiles.wingAirfoils)
      for (const auto& airfoil : profiles.wingAirfoils->wingAirfoil) definitions_.emplace(airfoil.uID, &airfoil);
    // Rotor blades are wings whose airfoils live beside the wing airfoils.
    if (profiles.rotorAirfoils)
      for (const auto& airfoil : profiles.rotorAirfoils->rotorAirfoil) definitions_.emplace(airfoil.uID, &airfoil);
  }

  std::shared_ptr<const WingProfile> get(const std::string& uid, const std::string& xpath) {
    if (const auto built = built_.find(uid); built != built_.end()) return built->second;
    const auto definition = definitions_.find(uid);
    if (definition == definitions_.end())
      throw Error(ErrorCode::InvalidModel, "airfoilUID '" + uid + "' names no wing airfoil", {}, xpath);
    auto profile = std::make_shared<const WingProfile>(WingProfile::fromDefinition(*definition->second));
    for (const Problem& warning : profile->warnings()) configuration_.warnAboutGeometry(warning);
    return built_[uid] = profile;
  }

 private:
  const Configuration& configuration_;
  std::unordered_map<std::string, const schema::ProfileGeometryType*> definitions_;
  std::unordered_map<std::string, std::shared_ptr<const WingProfile>> built_;
};

}  // namespace

gp_Pnt SegmentEnd::upper(double xsi) const { return model::apply(transform, profile->upper(xsi)); }
gp_Pnt SegmentEnd::lower(double xsi) const { return model::apply(transform, profile->lower(xsi)); }
gp_Pnt SegmentEnd::leadingEdge() const { return model::apply(transform, profile->leadingEdge()); }
gp_Pnt SegmentEnd::trailingEdge() const { return model::apply(transform, profile->trailingEdge()); }

std::shared_ptr<const WingGeometry> WingGeometry::of(const Configuration& configuration, const schema::WingType& wing) {
  return configuration.cache().obtain<WingGeometry>("wing-geometry:" + wing.uID, [&] {
    auto geometry = std::make_shared<WingGeometry>();
    geometry->configuration_ = &configuration;
    geometry->wing_ = &wing;
    AirfoilLibrary airfoils(configuration);
    std::unordered_map<std::string, SegmentEnd> ends;  // by element uID
    for (const auto& [uid, placed] : model::placedElements(configuration, wing))
      ends.emplace(uid, SegmentEnd{uid, airfoils.get(placed.element->airfoilUID, placed.element->xpath + "/airfoilUID"),
                                   placed.transform});
    if (!wing.segments) return std::shared_ptr<const WingGeometry>(geometry);
    std::vector<model::SegmentEnds> chain;
    for (const auto& segment : wing.segments->segment) chain.push_back({segment.fromElementUID, segment.toElementUID});
    for (std::size_t index : model::chainOrder(chain)) {
      const schema::WingSegmentType& segment = wing.segments->segment[index];
      auto end = [&](const std::string& uid, const char* which) {
        const auto found = ends.find(uid);
        if (found == ends.end())
          throw Error(ErrorCode::InvalidModel, std::string(which) + " '" + uid + "' names no element of this wing", {},
                      segment.xpath + "/" + which);
        return found->second;
      };
      geometry->segmentUids_.push_back(segment.uID);
      geometry->segments_.push_back({segment.uID, segment.xpath, end(segment.fromElementUID, "fromElementUID"),
                                     end(segment.toElementUID, "toElementUID")});
    }
    return std::shared_ptr<const WingGeometry>(geometry);
  });
}

const GuidedWingSkin* WingGeometry::guidedSkin() const {
  std::lock_guard<std::mutex> lock(guidedSkinMutex_);
  // A failure throws before the flag is set, so it is reported again by the next query.
  if (!guidedSkinBuilt_ && !segments_.empty()) guidedSkin_ = GuidedWingSkin::build(*configuration_, *wing_, segments_);
  guidedSkinBuilt_ = true;
  return guidedSkin_.get();
}

gp_Pnt WingGeometry::upperPoint(std::size_t segment, double eta, double xsi) const {
  if (const GuidedWingSkin* skin = guidedSkin()) return skin->upperPoint(segment, eta, xsi);
  const WingSegment& s = segments_[segment];
  return lerp(s.inner.upper(xsi), s.outer.upper(xsi), eta);
}

gp_Pnt WingGeometry::lowerPoint(std::size_t segment, double eta, double xsi) const {
  if (const GuidedWingSkin* skin = guidedSkin()) return skin->lowerPoint(segment, eta, xsi);
  const WingSegment& s = segments_[segment];
  return lerp(s.inner.lower(xsi), s.outer.lower(xsi), eta);
}

gp_Pnt WingGeometry::chordPoint(std::size_t segment, double eta, double xsi) const {
  const WingSegment& s = segments_[segment];
  return lerp(lerp(s.inner.leadingEdge(), s.inner.trailingEdge(), xsi),
              lerp(s.outer.leadingEdge(), s.outer.trailingEdge(), xsi), eta);
}

}  // namespace airshape::wing
