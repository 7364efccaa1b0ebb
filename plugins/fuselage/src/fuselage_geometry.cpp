#include "fuselage_geometry.h"

#include <unordered_map>

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/model/placed_elements.h"
#include "airshape/model/segment_chain.h"

namespace airshape::fuselage {

namespace {

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

/// The profile curve at eta: the blend of the segment's compatible profiles, pole by pole.
Handle(Geom_BSplineCurve) blend(const FuselageSegment& segment, double eta) {
  Handle(Geom_BSplineCurve) curve = Handle(Geom_BSplineCurve)::DownCast(segment.start->Copy());
  for (int i = 1; i <= curve->NbPoles(); ++i)
    curve->SetPole(i, gp_Pnt((1.0 - eta) * segment.start->Pole(i).XYZ() + eta * segment.end->Pole(i).XYZ()));
  return curve;
}

/// Whether a placed profile has shrunk to a point (a nose or tail tip).
bool isPoint(const Geom_BSplineCurve& curve) {
  for (int i = 2; i <= curve.NbPoles(); ++i)
    if (curve.Pole(i).Distance(curve.Pole(1)) > 1e-7) return false;
  return true;
}

void buildFaces(FuselageSegment& segment) {
  using namespace geometry;
  segment.skin = ruledFace(segment.start, segment.end);
  std::vector<Handle(Geom_BSplineCurve)> startBoundary = {segment.start}, endBoundary = {segment.end};
  if (!segment.closed) {  // a half profile: closed by straight edges and a flat face between them
    const auto startClosing = straightLine(segment.start->EndPoint(), segment.start->StartPoint());
    const auto endClosing = straightLine(segment.end->EndPoint(), segment.end->StartPoint());
    segment.symmetryFace = ruledFace(startClosing, endClosing);
    startBoundary.push_back(startClosing);
    endBoundary.push_back(endClosing);
  }
  try {  // a profile shrunk to a point needs no cap
    if (!isPoint(*segment.start)) segment.startCap = planarFace(startBoundary);
    if (!isPoint(*segment.end)) segment.endCap = planarFace(endBoundary);
    segment.solid = sewnSolid({segment.skin, segment.symmetryFace, segment.startCap, segment.endCap});
  } catch (const Error& error) {
    segment.solidProblem = "segment '" + segment.uid + "': " + error.message();
  }
}

const TopoDS_Shape& solidOf(const FuselageSegment& segment) {
  if (segment.solid.IsNull()) throw Error(ErrorCode::InvalidModel, segment.solidProblem);
  return segment.solid;
}

}  // namespace

std::shared_ptr<const FuselageGeometry> FuselageGeometry::of(const Configuration& configuration,
                                                             const schema::FuselageType& fuselage) {
  return configuration.cache().obtain<FuselageGeometry>("fuselage-geometry:" + fuselage.uID, [&] {
    auto geometry = std::make_shared<FuselageGeometry>();
    ProfileLibrary profiles(configuration.cpacs());
    const auto placed = model::placedElements(configuration, fuselage);
    if (!fuselage.segments) return std::shared_ptr<const FuselageGeometry>(geometry);
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
        return std::make_pair(geometry::transformed(profile.curve, found->second.transform), profile.closed);
      };
      const auto [start, startClosed] = end(definition.fromElementUID, "fromElementUID");
      const auto [finish, endClosed] = end(definition.toElementUID, "toElementUID");
      if (startClosed != endClosed)
        throw Error(ErrorCode::InvalidModel, "the segment joins a closed and an open profile", {}, definition.xpath);
      std::vector<Handle(Geom_BSplineCurve)> curves = {start, finish};
      geometry::makeCompatible(curves);
      FuselageSegment segment{definition.uID, curves[0], curves[1], startClosed, {}, {}, {}, {}, {}, {}};
      buildFaces(segment);
      geometry->segments_.push_back(segment);
      geometry->segmentUids_.push_back(definition.uID);
    }
    return std::shared_ptr<const FuselageGeometry>(geometry);
  });
}

gp_Pnt FuselageGeometry::point(std::size_t segment, double eta, double zeta) const {
  const FuselageSegment& s = segments_[segment];
  return gp_Pnt((1.0 - eta) * s.start->Value(zeta).XYZ() + eta * s.end->Value(zeta).XYZ());
}

double FuselageGeometry::circumference(std::size_t segment, double eta) const {
  GeomAdaptor_Curve curve(blend(segments_[segment], eta));
  return GCPnts_AbscissaPoint::Length(curve, 1e-10);
}

double FuselageGeometry::segmentVolume(std::size_t segment) const {
  return geometry::volumeOf(solidOf(segments_[segment]));
}

double FuselageGeometry::segmentSurfaceArea(std::size_t segment) const {
  return geometry::areaOf(segments_[segment].skin);
}

double FuselageGeometry::volume() const {
  double total = 0.0;
  for (std::size_t k = 0; k < segments_.size(); ++k) total += segmentVolume(k);
  return total;
}

double FuselageGeometry::surfaceArea() const {
  double total = 0.0;
  for (std::size_t k = 0; k < segments_.size(); ++k) total += segmentSurfaceArea(k);
  return total;
}

TopoDS_Shape FuselageGeometry::solid() const {
  if (segments_.empty()) throw Error(ErrorCode::InvalidModel, "the fuselage has no segments, so no solid");
  std::vector<TopoDS_Face> faces = {segments_.front().startCap, segments_.back().endCap};
  for (const FuselageSegment& segment : segments_) {
    faces.push_back(segment.skin);
    faces.push_back(segment.symmetryFace);
  }
  return geometry::sewnSolid(faces);
}

}  // namespace airshape::fuselage
