#include "fuselage_geometry.h"

#include <algorithm>
#include <optional>
#include <unordered_map>

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAdaptor_Curve.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/gordon_surface.h"
#include "airshape/geometry/loft_piece.h"
#include "airshape/geometry/skinning.h"
#include "airshape/model/guide_curves.h"
#include "airshape/model/placed_elements.h"
#include "airshape/model/segment_chain.h"

namespace airshape::fuselage {

namespace {

/// With guide curves the loft blends linearly between neighbouring profiles (the guides
/// shape it in between), as the reference's guided lofts do; see docs/fuselage.md.
constexpr int kDegreeAcrossProfiles = 1;

/// The fuselage profiles of the document by uID, built on demand.
class ProfileLibrary {
 public:
  explicit ProfileLibrary(const schema::CpacsType& cpacs) {
    if (cpacs.vehicles && cpacs.vehicles->profiles && cpacs.vehicles->profiles->fuselageProfiles)
      for (const auto& profile : cpacs.vehicles->profiles->fuselageProfiles->fuselageProfile)
        definitions_.emplace(profile.uID, &profile);
  }

  const FuselageProfile& get(const std::string& uid, const std::string& xpath) {
    if (const auto built = built_.find(uid); built != built_.end()) return built->second;
    const auto definition = definitions_.find(uid);
    if (definition == definitions_.end())
      throw Error(ErrorCode::InvalidModel, "profileUID '" + uid + "' names no fuselage profile", {}, xpath);
    return built_.emplace(uid, FuselageProfile::fromDefinition(*definition->second)).first->second;
  }

 private:
  std::unordered_map<std::string, const schema::ProfileGeometryType*> definitions_;
  std::unordered_map<std::string, FuselageProfile> built_;
};

const TopoDS_Shape& solidOf(const geometry::LoftPiece& segment) {
  if (segment.solid.IsNull()) throw Error(ErrorCode::InvalidModel, segment.solidProblem);
  return segment.solid;
}

/// The parameter of the point of `curve` at `target` (within 1e-7), found by Newton's method
/// from `start`; nothing when it does not get there.
std::optional<double> nearbyParameter(const Geom_BSplineCurve& curve, const gp_Pnt& target, double start) {
  constexpr double kOnCurve = 1e-7;
  double t = std::clamp(start, curve.FirstParameter(), curve.LastParameter());
  for (int step = 0; step < 20; ++step) {
    gp_Pnt p;
    gp_Vec d1, d2;
    curve.D2(t, p, d1, d2);
    if (p.Distance(target) <= kOnCurve) return t;
    const gp_Vec offset(target, p);
    const double slope = offset.Dot(d1), curvature = offset.Dot(d2) + d1.SquareMagnitude();
    if (!(curvature > 0.0)) return std::nullopt;
    t = std::clamp(t - slope / curvature, curve.FirstParameter(), curve.LastParameter());
  }
  return std::nullopt;
}

}  // namespace

std::shared_ptr<const FuselageGeometry> FuselageGeometry::of(const Configuration& configuration,
                                                             const schema::FuselageType& fuselage) {
  return configuration.cache().obtain<FuselageGeometry>("fuselage-geometry:" + fuselage.uID, [&] {
    auto geometry = std::make_shared<FuselageGeometry>();
    ProfileLibrary profiles(configuration.cpacs());
    const auto placed = model::placedElements(configuration, fuselage);
    if (!fuselage.segments) return std::shared_ptr<const FuselageGeometry>(geometry);
    std::vector<PlacedProfile> sections;  // in chain order
    std::vector<const schema::GuideCurvesType*> guidesPerSegment;
    std::vector<std::string> segmentXpaths;
    std::vector<model::SegmentEnds> chain;
    for (const auto& segment : fuselage.segments->segment)
      chain.push_back({segment.fromElementUID, segment.toElementUID});
    for (std::size_t index : model::chainOrder(chain)) {
      const schema::FuselageSegmentType& definition = fuselage.segments->segment[index];
      auto end = [&](const std::string& uid, const char* which) {
        const auto found = placed.find(uid);
        if (found == placed.end())
          throw Error(ErrorCode::InvalidModel, std::string(which) + " '" + uid + "' names no element of this fuselage",
                      {}, definition.xpath + "/" + which);
        const FuselageProfile& profile =
            profiles.get(found->second.element->profileUID, found->second.element->xpath + "/profileUID");
        if (!sections.empty() && profile.closed != geometry->closedProfiles_)
          throw Error(ErrorCode::InvalidModel, "the fuselage mixes closed and open (half) profiles", {},
                      definition.xpath);
        geometry->closedProfiles_ = profile.closed;
        return PlacedProfile{geometry::transformed(profile.curve, found->second.transform), found->second.transform,
                             &profile};
      };
      if (sections.empty()) sections.push_back(end(definition.fromElementUID, "fromElementUID"));
      sections.push_back(end(definition.toElementUID, "toElementUID"));
      guidesPerSegment.push_back(definition.guideCurves ? &*definition.guideCurves : nullptr);
      geometry->segmentUids_.push_back(definition.uID);
      segmentXpaths.push_back(definition.xpath);
    }
    if (model::hasGuideCurves(guidesPerSegment))
      geometry->loftWithGuides(sections, fuselageGuideCurves(configuration.cpacs(), sections, guidesPerSegment));
    else
      geometry->loft(sections);
    geometry->cutIntoSegments(segmentXpaths);
    return std::shared_ptr<const FuselageGeometry>(geometry);
  });
}

void FuselageGeometry::loft(const std::vector<PlacedProfile>& sections) {
  using namespace geometry;
  for (const PlacedProfile& section : sections) profiles_.push_back(section.curve);
  makeCompatible(profiles_);
  // One smooth skin through every profile (cubic where there are enough of them), so the
  // fuselage has no creases at its sections; each segment is the skin between two of them.
  sectionSites_ = averagedSectionParameters(profiles_);
  loft_ = skinCurves(profiles_, sectionSites_, skinningSpace(sectionSites_, 3, false));
}

void FuselageGeometry::loftWithGuides(const std::vector<PlacedProfile>& sections, const FuselageGuides& guides) {
  for (const PlacedProfile& section : sections) profiles_.push_back(section.curve);
  const geometry::GordonSurface gordon =
      geometry::buildGordonSurface(profiles_, guides.curves, {}, &guides.crossings, kDegreeAcrossProfiles);
  if (gordon.profileSites.size() != profiles_.size())
    throw Error(ErrorCode::InvalidModel, "the guide curves do not cross every profile of the fuselage once");
  loft_ = gordon.surface;
  sectionSites_ = gordon.profileSites;
  guided_ = true;
  for (double v : sectionSites_) sectionIsoCurves_.push_back(Handle(Geom_BSplineCurve)::DownCast(loft_->VIso(v)));
}

void FuselageGeometry::cutIntoSegments(const std::vector<std::string>& segmentXpaths) {
  for (std::size_t k = 0; k < segmentUids_.size(); ++k) {
    FuselageSegment segment;
    segment.uid = segmentUids_[k];
    segment.vStart = sectionSites_[k];
    segment.vEnd = sectionSites_[k + 1];
    if (!(segment.vEnd > segment.vStart))
      throw Error(ErrorCode::InvalidModel, "the segment's two profiles coincide", {}, segmentXpaths[k]);
    segments_.push_back(segment);
  }
  segmentPieces_.resize(segments_.size());
}

double FuselageGeometry::loftParameterOf(std::size_t section, double zeta) const {
  if (!guided_) return zeta;
  // The Gordon surface runs the profiles at parameters of its own: find where this
  // profile's point at zeta lies on the surface's iso-curve there. The two parameters are
  // close where a guide sits at the profile's start, so Newton's method from zeta usually
  // lands in a few steps; where it does not, a global projection decides.
  const gp_Pnt target = profiles_[section]->Value(zeta);
  const Geom_BSplineCurve& iso = *sectionIsoCurves_[section];
  if (const auto near = nearbyParameter(iso, target, zeta)) return *near;
  GeomAPI_ProjectPointOnCurve projection(target, sectionIsoCurves_[section]);
  return projection.NbPoints() > 0 ? projection.LowerDistanceParameter() : zeta;
}

geometry::LoftPiece FuselageGeometry::piece(std::size_t from, std::size_t to, const std::string& name) const {
  geometry::LoftPiece piece = geometry::loftPiece(loft_, sectionSites_[from], sectionSites_[to], closedProfiles_);
  if (!piece.solidProblem.empty()) piece.solidProblem = name + ": " + piece.solidProblem;
  return piece;
}

TopoDS_Face FuselageGeometry::skinFace(std::size_t from, std::size_t to) const {
  return geometry::loftFace(loft_, sectionSites_[from], sectionSites_[to]);
}

const geometry::LoftPiece& FuselageGeometry::segmentPiece(std::size_t segment) const {
  std::lock_guard<std::mutex> lock(piecesMutex_);
  auto& built = segmentPieces_[segment];
  if (!built)
    built =
        std::make_unique<geometry::LoftPiece>(piece(segment, segment + 1, "segment '" + segments_[segment].uid + "'"));
  return *built;
}

double FuselageGeometry::vAt(std::size_t segment, double eta) const {
  const FuselageSegment& s = segments_[segment];
  return s.vStart + eta * (s.vEnd - s.vStart);
}

gp_Pnt FuselageGeometry::point(std::size_t segment, double eta, double zeta) const {
  const double u = (1.0 - eta) * loftParameterOf(segment, zeta) + eta * loftParameterOf(segment + 1, zeta);
  return loft_->Value(u, vAt(segment, eta));
}

double FuselageGeometry::circumference(std::size_t segment, double eta) const {
  GeomAdaptor_Curve curve(loft_->VIso(vAt(segment, eta)));
  return GCPnts_AbscissaPoint::Length(curve, 1e-10);
}

double FuselageGeometry::segmentVolume(std::size_t segment) const {
  return geometry::volumeOf(solidOf(segmentPiece(segment)));
}

double FuselageGeometry::segmentSurfaceArea(std::size_t segment) const {
  return geometry::areaOf(segmentPiece(segment).skin);
}

double FuselageGeometry::volume() const {
  if (segments_.empty()) return 0.0;
  // One skin face over the whole loft and its two caps: quicker than the named solid.
  const geometry::LoftPiece whole = piece(0, segments_.size(), "the fuselage");
  if (!whole.solid.IsNull()) return geometry::volumeOf(whole.solid);
  double total = 0.0;  // sewing can fail on one face with many degenerate spans; segments do not
  for (std::size_t k = 0; k < segments_.size(); ++k) total += segmentVolume(k);
  return total;
}

double FuselageGeometry::surfaceArea() const {
  return segments_.empty() ? 0.0 : geometry::areaOf(skinFace(0, segments_.size()));
}

NamedShape FuselageGeometry::solid(const std::string& fuselageUid) const {
  if (segments_.empty()) throw Error(ErrorCode::InvalidModel, "the fuselage has no segments, so no solid");
  const double vFirst = sectionSites_.front(), vLast = sectionSites_.back();
  std::vector<std::pair<std::string, TopoDS_Face>> named;
  try {
    named = {{fuselageUid + "/front", geometry::loftCap(loft_, vFirst, closedProfiles_)},
             {fuselageUid + "/rear", geometry::loftCap(loft_, vLast, closedProfiles_)}};
  } catch (const Error& error) {
    throw Error(error.code(), "the fuselage: " + error.message());
  }
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    named.emplace_back(segments_[k].uid + "/skin", skinFace(k, k + 1));
    if (!closedProfiles_)
      named.emplace_back(segments_[k].uid + "/symmetry",
                         geometry::loftClosingFace(loft_, sectionSites_[k], sectionSites_[k + 1]));
  }
  try {
    return sewnNamedSolid(named);
  } catch (const Error& error) {
    throw Error(error.code(), "the fuselage: " + error.message());
  }
}

}  // namespace airshape::fuselage
