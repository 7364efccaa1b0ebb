#include "fuselage_geometry.h"

#include <algorithm>
#include <optional>
#include <set>
#include <unordered_map>

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Standard_Failure.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/coons_patches.h"
#include "airshape/geometry/gordon_surface.h"
#include "airshape/geometry/loft_piece.h"
#include "airshape/geometry/loft_shell.h"
#include "airshape/geometry/skinning.h"
#include "airshape/model/guide_curves.h"
#include "airshape/model/placed_elements.h"
#include "airshape/model/segment_chain.h"
#include "airshape/parallel_for.h"

namespace airshape::fuselage {

namespace {

/// With guide curves the loft blends linearly between neighbouring profiles (the guides
/// shape it in between), as the reference's guided lofts do; see docs/fuselage.md.
constexpr int kDegreeAcrossProfiles = 1;

/// The fuselage profiles of the document by uID, built on demand.
class ProfileLibrary {
 public:
  explicit ProfileLibrary(const Configuration& configuration) : configuration_(configuration) {
    const schema::CpacsType& cpacs = configuration.cpacs();
    if (cpacs.vehicles && cpacs.vehicles->profiles && cpacs.vehicles->profiles->fuselageProfiles)
      for (const auto& profile : cpacs.vehicles->profiles->fuselageProfiles->fuselageProfile)
        definitions_.emplace(profile.uID, &profile);
  }

  /// Builds the profiles of these uIDs on every core ahead of their use: a fuselage's point-list
  /// profiles are fitted one by one otherwise. One that names nothing or cannot be built is
  /// left to get(), which says why.
  void prefetch(const std::vector<std::string>& uids) {
    std::vector<const schema::ProfileGeometryType*> wanted;
    for (const std::string& uid : std::set<std::string>(uids.begin(), uids.end()))
      if (const auto definition = definitions_.find(uid); definition != definitions_.end() && !built_.count(uid))
        wanted.push_back(definition->second);
    std::vector<std::optional<FuselageProfile>> fitted(wanted.size());
    parallelFor(wanted.size(), [&](std::size_t i) {
      try {
        fitted[i] = FuselageProfile::fromDefinition(*wanted[i]);
      } catch (...) {  // get() builds it again and reports the error with its path
      }
    });
    for (std::size_t i = 0; i < wanted.size(); ++i)
      if (fitted[i]) built_.emplace(wanted[i]->uID, std::move(*fitted[i]));
  }

  /// The profile of `uid` (its warnings said on its first use, in the order of use).
  const FuselageProfile& get(const std::string& uid, const std::string& xpath) {
    auto built = built_.find(uid);
    if (built == built_.end()) {
      const auto definition = definitions_.find(uid);
      if (definition == definitions_.end())
        throw Error(ErrorCode::InvalidModel, "profileUID '" + uid + "' names no fuselage profile", {}, xpath);
      built = built_.emplace(uid, FuselageProfile::fromDefinition(*definition->second)).first;
    }
    if (used_.insert(uid).second)
      for (const Problem& warning : built->second.warnings) configuration_.warnAboutGeometry(warning);
    return built->second;
  }

 private:
  const Configuration& configuration_;
  std::unordered_map<std::string, const schema::ProfileGeometryType*> definitions_;
  std::unordered_map<std::string, FuselageProfile> built_;
  std::set<std::string> used_;  ///< profiles whose warnings were said
};

/// The piece's solid; where it has none, an error naming `xpath`.
const TopoDS_Shape& solidOf(const geometry::LoftPiece& piece, const std::string& xpath) {
  if (piece.solid.IsNull()) throw Error(ErrorCode::InvalidModel, piece.solidProblem, {}, xpath);
  return piece.solid;
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

/// Whether a profile runs smoothly (C2) through parameter t: no knot of multiplicity above
/// degree − 2 there; through its seam only when it is periodic.
bool smoothThrough(const Geom_BSplineCurve& curve, double t) {
  const double first = curve.FirstParameter(), last = curve.LastParameter(), tolerance = 1e-9 * (last - first);
  if (std::abs(t - first) < tolerance || std::abs(t - last) < tolerance) return curve.IsPeriodic();
  for (int i = 1; i <= curve.NbKnots(); ++i)
    if (std::abs(curve.Knot(i) - t) < tolerance) return curve.Degree() - curve.Multiplicity(i) >= 2;
  return true;
}

}  // namespace

std::shared_ptr<const FuselageGeometry> FuselageGeometry::of(const Configuration& configuration,
                                                             const schema::FuselageType& fuselage) {
  return build(configuration, fuselage, model::componentTransform(configuration, fuselage.uID));
}

std::shared_ptr<const FuselageGeometry> FuselageGeometry::of(const Configuration& configuration,
                                                             const schema::FuselageType& body,
                                                             const model::Transform& placement) {
  return build(configuration, body, placement);
}

std::shared_ptr<const FuselageGeometry> FuselageGeometry::of(const Configuration& configuration,
                                                             const schema::DuctType& duct) {
  return build(configuration, duct, model::componentTransform(configuration, duct.uID));
}

template <class Body>
std::shared_ptr<const FuselageGeometry> FuselageGeometry::build(const Configuration& configuration,
                                                                const Body& fuselage,
                                                                const model::Transform& placement) {
  return configuration.cache().obtain<FuselageGeometry>("fuselage-geometry:" + fuselage.uID, [&] {
    auto geometry = std::make_shared<FuselageGeometry>();
    geometry->xpath_ = fuselage.xpath;
    ProfileLibrary profiles(configuration);
    const auto placed = model::placedElements(fuselage, placement);
    if (!fuselage.segments) return std::shared_ptr<const FuselageGeometry>(geometry);
    std::vector<std::string> profileUids;
    for (const auto& [uid, element] : placed) profileUids.push_back(element.element->profileUID);
    profiles.prefetch(profileUids);
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
                             &profile, uid};
      };
      if (sections.empty()) sections.push_back(end(definition.fromElementUID, "fromElementUID"));
      sections.push_back(end(definition.toElementUID, "toElementUID"));
      guidesPerSegment.push_back(definition.guideCurves ? &*definition.guideCurves : nullptr);
      geometry->segmentUids_.push_back(definition.uID);
      segmentXpaths.push_back(definition.xpath);
    }
    const bool guided = model::hasGuideCurves(guidesPerSegment);
    try {
      if (guided)
        geometry->loftWithGuides(sections, fuselageGuideCurves(configuration.cpacs(), sections, guidesPerSegment));
      else
        geometry->loft(sections);
      geometry->cutIntoSegments(segmentXpaths);
    } catch (const Error& error) {
      // Geometry errors deep in the loft know no node; the fuselage's segments are where
      // to look.
      if (!error.cpacsPath().empty()) throw;
      throw Error(error.code(), std::string(guided ? "the guided skin: " : "the loft: ") + error.message(), {},
                  fuselage.xpath + "/segments");
    }
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
  guided_ = true;
  if (closedProfiles_ || guidesAlongBothEnds(guides)) return patchRings(sections, guides);
  const geometry::GordonSurface gordon =
      geometry::buildGordonSurface(profiles_, guides.curves, {}, &guides.crossings, kDegreeAcrossProfiles);
  if (gordon.profileSites.size() != profiles_.size())
    throw Error(ErrorCode::InvalidModel, "the guide curves do not cross every profile of the fuselage once");
  loft_ = gordon.surface;
  sectionSites_ = gordon.profileSites;
  for (double v : sectionSites_) sectionIsoCurves_.push_back(Handle(Geom_BSplineCurve)::DownCast(loft_->VIso(v)));
}

bool FuselageGeometry::guidesAlongBothEnds(const FuselageGuides& guides) const {
  const auto& p = guides.crossings.profileParameters;
  for (Eigen::Index k = 0; k < p.rows(); ++k) {
    const Geom_BSplineCurve& profile = *profiles_[static_cast<std::size_t>(k)];
    const double first = profile.FirstParameter(), last = profile.LastParameter(), tolerance = 1e-9 * (last - first);
    if (!((p.row(k).array() - first).abs() < tolerance).any() || !((p.row(k).array() - last).abs() < tolerance).any())
      return false;
  }
  return true;
}

void FuselageGeometry::patchRings(const std::vector<PlacedProfile>& sections, const FuselageGuides& guides) {
  // The guides in the order they cross the first profile; one that repeats another's place
  // (relative circumference 1 on a closed profile is 0) is left out.
  const auto& p = guides.crossings.profileParameters;
  const Eigen::Index K = p.rows();
  std::vector<Eigen::Index> order;
  for (Eigen::Index l = 0; l < p.cols(); ++l) order.push_back(l);
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return p(0, a) < p(0, b); });
  auto period = [&](Eigen::Index k) {
    return profiles_[static_cast<std::size_t>(k)]->LastParameter() -
           profiles_[static_cast<std::size_t>(k)]->FirstParameter();
  };
  auto samePlace = [&](Eigen::Index a, Eigen::Index b) {
    const double gap = std::abs(p(0, a) - p(0, b));
    return gap < 1e-9 || (closedProfiles_ && std::abs(gap - period(0)) < 1e-9);
  };
  std::vector<Eigen::Index> kept;
  for (Eigen::Index l : order)
    if (std::none_of(kept.begin(), kept.end(), [&](Eigen::Index k) { return samePlace(k, l); })) kept.push_back(l);

  // On closed profiles the ring of cells closes with the first guide once more, one period
  // on; half profiles have guides along both ends and no ring.
  const auto L = static_cast<Eigen::Index>(kept.size());
  const Eigen::Index columns = closedProfiles_ ? L + 1 : L;
  geometry::KnownCrossings ring;
  ring.profileParameters.resize(K, columns);
  ring.guideParameters.resize(K, columns);
  std::vector<Handle(Geom_BSplineCurve)> curves;
  std::vector<const std::vector<bool>*> smooth;
  for (Eigen::Index j = 0; j < columns; ++j) {
    const Eigen::Index l = kept[static_cast<std::size_t>(j % L)];
    curves.push_back(guides.curves[static_cast<std::size_t>(l)]);
    smooth.push_back(&guides.smoothAt[static_cast<std::size_t>(l)]);
    for (Eigen::Index k = 0; k < K; ++k) {
      ring.profileParameters(k, j) = p(k, l) + (j == L ? period(k) : 0.0);
      ring.guideParameters(k, j) = guides.crossings.guideParameters(k, l);
    }
    const double start = guides.startPositions[static_cast<std::size_t>(l)];
    cellParameters_.push_back(j == L ? cellParameters_.front() + 1.0 : start);
  }
  // A cell is rounded where a curve runs smoothly (C2) through one of its corners, a guide
  // through a profile inside one interpolated part or a profile through a guide, and
  // bilinear otherwise: the reference's rule (see docs/fuselage.md).
  auto profileSmoothAt = [&](std::size_t k, std::size_t j) {
    return smoothThrough(*profiles_[k], p(static_cast<Eigen::Index>(k), kept[j % kept.size()]));
  };
  auto guideUid = [&](std::size_t j) { return guides.uids[static_cast<std::size_t>(kept[j % kept.size()])]; };
  patchRows_ = geometry::buildCoonsPatchRows(
      profiles_, curves, ring,
      [&](std::size_t k, std::size_t l) {
        for (std::size_t j : {l, l + 1})
          if ((*smooth[j])[k] || (*smooth[j])[k + 1] || profileSmoothAt(k, j) || profileSmoothAt(k + 1, j))
            return geometry::PatchBlending::Rounded;
        return geometry::PatchBlending::Bilinear;
      },
      [&](std::size_t k, std::size_t l) {
        return "the cell between the profiles of elements '" + sections[k].elementUid + "' and '" +
               sections[k + 1].elementUid + "' and between guide curves '" + guideUid(l) + "' and '" + guideUid(l + 1) +
               "'";
      });
  sectionSites_.assign(ring.guideParameters.col(0).data(), ring.guideParameters.col(0).data() + K);
}

void FuselageGeometry::cutIntoSegments(const std::vector<std::string>& segmentXpaths) {
  for (std::size_t k = 0; k < segmentUids_.size(); ++k) {
    FuselageSegment segment;
    segment.uid = segmentUids_[k];
    segment.xpath = segmentXpaths[k];
    segment.vStart = sectionSites_[k];
    segment.vEnd = sectionSites_[k + 1];
    if (!(segment.vEnd > segment.vStart))
      throw Error(ErrorCode::InvalidModel, "the segment's two profiles coincide", {}, segmentXpaths[k]);
    segments_.push_back(segment);
  }
  for (std::size_t k = 0; k < segments_.size(); ++k) segmentPieces_.push_back(std::make_unique<CachedPiece>());
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

geometry::LoftPiece FuselageGeometry::piece(std::size_t from, std::size_t to) const {
  return patchRows_.empty() ? geometry::loftPiece(loft_, sectionSites_[from], sectionSites_[to], closedProfiles_)
                            : geometry::loftPiece(patchRows_[from], 0.0, 1.0, closedProfiles_);
}

TopoDS_Face FuselageGeometry::skinFace(std::size_t from, std::size_t to) const {
  if (!patchRows_.empty()) return geometry::loftFace(patchRows_[from], 0.0, 1.0);
  return geometry::loftFace(loft_, sectionSites_[from], sectionSites_[to]);
}

const geometry::LoftPiece& FuselageGeometry::segmentPiece(std::size_t segment) const {
  CachedPiece& cached = *segmentPieces_[segment];
  std::call_once(cached.built,
                 [&] { cached.piece = std::make_unique<geometry::LoftPiece>(piece(segment, segment + 1)); });
  return *cached.piece;
}

double FuselageGeometry::vAt(std::size_t segment, double eta) const {
  const FuselageSegment& s = segments_[segment];
  return s.vStart + eta * (s.vEnd - s.vStart);
}

gp_Pnt FuselageGeometry::point(std::size_t segment, double eta, double zeta) const {
  if (!patchRows_.empty()) {
    // Cell l lies between the guides at cellParameters_[l] and [l+1] (relative
    // circumferences), over u in [l, l+1] of the segment's ring; zeta maps linearly onto it.
    const std::vector<double>& at = cellParameters_;
    if (zeta < at.front()) zeta += 1.0;
    std::size_t l = 0;
    while (l + 2 < at.size() && zeta > at[l + 1]) ++l;
    const double share = std::clamp((zeta - at[l]) / (at[l + 1] - at[l]), 0.0, 1.0);
    return patchRows_[segment]->Value(static_cast<double>(l) + share, eta);
  }
  const double u = (1.0 - eta) * loftParameterOf(segment, zeta) + eta * loftParameterOf(segment + 1, zeta);
  return loft_->Value(u, vAt(segment, eta));
}

double FuselageGeometry::circumference(std::size_t segment, double eta) const {
  GeomAdaptor_Curve curve(patchRows_.empty() ? loft_->VIso(vAt(segment, eta)) : patchRows_[segment]->VIso(eta));
  return GCPnts_AbscissaPoint::Length(curve, 1e-10);
}

double FuselageGeometry::segmentVolume(std::size_t segment) const {
  return geometry::volumeOf(solidOf(segmentPiece(segment), segments_[segment].xpath));
}

double FuselageGeometry::segmentSurfaceArea(std::size_t segment) const {
  return geometry::areaOf(segmentPiece(segment).skin);
}

double FuselageGeometry::sumOverSegments(const std::function<double(std::size_t segment)>& measure) const {
  std::vector<double> measures(segments_.size(), 0.0);
  parallelFor(segments_.size(), [&](std::size_t k) { measures[k] = measure(k); });
  double total = 0.0;  // added in the segments' order, whichever core measured which
  for (double value : measures) total += value;
  return total;
}

double FuselageGeometry::volume() const {
  if (segments_.empty()) return 0.0;
  // The skin and the two caps sharing their edges from the start: no sewing (which took two
  // thirds of opening D150 and asking its volumes).
  if (closedProfiles_) {
    try {
      std::vector<TopoDS_Face> faces;
      if (patchRows_.empty())
        return geometry::volumeOf(
            geometry::closedLoftSolid(loft_, {sectionSites_.front(), sectionSites_.back()}, faces));
      std::vector<geometry::LoftStretch> rows;
      for (const auto& row : patchRows_) rows.push_back({row, 0.0, 1.0});
      return geometry::volumeOf(geometry::closedLoftSolid(rows, faces));
    } catch (const Error&) {
    } catch (const Standard_Failure&) {
    }
  }
  if (!patchRows_.empty())  // a ring of patches per segment: the segments' solids
    return sumOverSegments([this](std::size_t k) { return segmentVolume(k); });
  const geometry::LoftPiece whole = piece(0, segments_.size());
  if (!whole.solid.IsNull()) return geometry::volumeOf(whole.solid);
  // Sewing can fail on one face with many degenerate spans; segments do not.
  return sumOverSegments([this](std::size_t k) { return segmentVolume(k); });
}

double FuselageGeometry::surfaceArea() const {
  if (!patchRows_.empty()) return sumOverSegments([this](std::size_t k) { return segmentSurfaceArea(k); });
  return segments_.empty() ? 0.0 : geometry::areaOf(skinFace(0, segments_.size()));
}

NamedShape FuselageGeometry::solid(const std::string& fuselageUid) const {
  if (segments_.empty()) throw Error(ErrorCode::InvalidModel, "the fuselage has no segments, so no solid", {}, xpath_);
  if (closedProfiles_) {
    // A loft (or a row of guide-curve patches per segment) of closed profiles: its faces
    // share their edges from the start, several times quicker than sewing them; sewing stays
    // for half profiles and for what that cannot take.
    try {
      return solidOfSharedEdges(fuselageUid);
    } catch (const Error&) {
    } catch (const Standard_Failure&) {
    }
  }
  std::vector<std::pair<std::string, TopoDS_Face>> named;
  try {
    if (patchRows_.empty())
      named = {{fuselageUid + "/front", geometry::loftCap(loft_, sectionSites_.front(), closedProfiles_)},
               {fuselageUid + "/rear", geometry::loftCap(loft_, sectionSites_.back(), closedProfiles_)}};
    else
      named = {{fuselageUid + "/front", geometry::profileCap(profiles_.front(), closedProfiles_)},
               {fuselageUid + "/rear", geometry::profileCap(profiles_.back(), closedProfiles_)}};
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, xpath_);
  }
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    named.emplace_back(segments_[k].uid + "/skin", skinFace(k, k + 1));
    if (!closedProfiles_)
      named.emplace_back(segments_[k].uid + "/symmetry",
                         patchRows_.empty() ? geometry::loftClosingFace(loft_, sectionSites_[k], sectionSites_[k + 1])
                                            : geometry::loftClosingFace(patchRows_[k], 0.0, 1.0));
  }
  try {
    return sewnNamedSolid(named);
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, xpath_);
  }
}

NamedShape FuselageGeometry::solidOfSharedEdges(const std::string& fuselageUid) const {
  std::vector<TopoDS_Face> faces;
  NamedShape solid;
  if (patchRows_.empty()) {
    solid.shape = geometry::closedLoftSolid(loft_, sectionSites_, faces);
  } else {  // a row of guide-curve patches per segment
    std::vector<geometry::LoftStretch> rows;
    for (const auto& row : patchRows_) rows.push_back({row, 0.0, 1.0});
    solid.shape = geometry::closedLoftSolid(rows, faces);
  }
  if (!faces.front().IsNull()) solid.faces.emplace_back(fuselageUid + "/front", faces.front());
  for (std::size_t k = 0; k < segments_.size(); ++k) solid.faces.emplace_back(segments_[k].uid + "/skin", faces[k + 1]);
  if (!faces.back().IsNull()) solid.faces.emplace_back(fuselageUid + "/rear", faces.back());
  return solid;
}

NamedShape FuselageGeometry::segmentSolid(std::size_t segment) const {
  const geometry::LoftPiece& piece = segmentPiece(segment);
  const std::string& uid = segments_[segment].uid;
  solidOf(piece, segments_[segment].xpath);  // says why where there is none
  try {
    return sewnNamedSolid({{uid + "/skin", piece.skin},
                           {uid + "/symmetry", piece.closingFace},
                           {uid + "/front", piece.startCap},
                           {uid + "/rear", piece.endCap}});
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, segments_[segment].xpath);
  }
}

}  // namespace airshape::fuselage
