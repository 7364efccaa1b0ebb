// The fuselage plugin: CPACS fuselages and ducts, lofted from their sections of fuselage
// profiles, and the fuselage ops. It offers the same loft to other plugins (tank vessels)
// through its public interface (airshape/fuselage/fuselage_services.h).
#include <algorithm>

#include <gp_Trsf.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/fused_shape.h"
#include "airshape/model/primary_model.h"
#include "airshape/model/symmetry.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/query/arguments.h"
#include "airshape/query/model_selection.h"
#include "fuselage_geometry.h"
#include "fuselage_services.h"

namespace airshape::fuselage {

using query::Json;

namespace {

/// The fuselage a query names by index or uID, in the model queries address (the first one).
schema::FuselageType& selectFuselage(const Configuration& configuration, const Json& query) {
  return query::selectInFirstModel(configuration, model::primaryModel(configuration).fuselages, query, "fuselage",
                                   "fuselage");
}

/// Every duct of every aircraft model.
std::vector<const schema::DuctType*> everyDuct(const Configuration& configuration) {
  std::vector<const schema::DuctType*> ducts;
  const auto& vehicles = configuration.cpacs().vehicles;
  if (vehicles && vehicles->aircraft)
    for (const auto& model : vehicles->aircraft->model)
      if (model.ducts)
        for (const auto& duct : model.ducts->duct) ducts.push_back(&duct);
  return ducts;
}

/// The duct of this uID, or null.
const schema::DuctType* ductNamed(const Configuration& configuration, const std::string& uid) {
  for (const schema::DuctType* duct : everyDuct(configuration))
    if (duct->uID == uid) return duct;
  return nullptr;
}

/// The duct assembly of this uID; throws Error when there is none.
const schema::DuctAssemblyType& ductAssemblyNamed(const Configuration& configuration, const std::string& uid) {
  const auto& vehicles = configuration.cpacs().vehicles;
  if (vehicles && vehicles->aircraft)
    for (const auto& model : vehicles->aircraft->model)
      if (model.ducts)
        for (const auto& assembly : model.ducts->ductAssembly)
          if (assembly.uID == uid) return assembly;
  throw Error(ErrorCode::InvalidArgument, "no duct or duct assembly with uID '" + uid + "'");
}

/// A duct assembly: the Boolean union of its ducts, with the mirrored halves of those that
/// have a symmetry plane (the cutting tool the schema applies to wings and fuselages).
NamedShape ductAssemblySolid(const Configuration& configuration, const schema::DuctAssemblyType& assembly) {
  std::vector<const NamedShape*> ducts;
  if (assembly.ductUIDs)
    for (const std::string& uid : assembly.ductUIDs->uID) {
      if (ductNamed(configuration, uid) == nullptr)
        throw Error(ErrorCode::InvalidModel, "'" + uid + "' names no duct", {}, assembly.xpath + "/ductUIDs");
      ducts.push_back(&configuration.shapes().namedShapeOf(configuration, uid));
      if (model::resolvedSymmetry(configuration, uid) != "none")
        ducts.push_back(&configuration.shapes().mirroredShapeOf(configuration, uid));
    }
  if (ducts.empty()) throw NoShape("the duct assembly names no ducts: no shape", assembly.xpath);
  // One duct is copied: an export names the faces of each component, which two components
  // sharing faces would confuse.
  if (ducts.size() == 1) return transformedNamedShape(*ducts.front(), gp_Trsf());
  return fuseNamedShapes(ducts);
}

/// The duct holding a duct segment of this uID.
const schema::DuctType& ductHolding(const Configuration& configuration, const std::string& segmentUid) {
  for (const schema::DuctType* duct : everyDuct(configuration))
    if (duct->segments)
      for (const auto& segment : duct->segments->segment)
        if (segment.uID == segmentUid) return *duct;
  throw Error(ErrorCode::InvalidArgument, "no duct segment with uID '" + segmentUid + "'");
}

std::size_t segmentOf(const FuselageGeometry& geometry, const Json& q) {
  return query::selectByIndexOrUid(q, "segment", geometry.segmentUids(), "segment");
}

class FuselagePlugin final : public plugin::BasicPlugin {
 public:
  void offerServices(plugin::ServiceRegistry& services) const override {
    services.offer<FuselageServices>(kFuselageServices, makeFuselageServices());
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    shapes.add("fuselage", [](const Configuration& c, const std::string& uid) {
      const model::ModelComponents& model = model::modelHolding(c, uid);
      return FuselageGeometry::of(c, model::findByUid(c, model, model.fuselages, uid, "fuselage"))->solid(uid);
    });
    shapes.add("duct", [](const Configuration& c, const std::string& uid) {
      if (const schema::DuctType* duct = ductNamed(c, uid)) return FuselageGeometry::of(c, *duct)->solid(uid);
      return ductAssemblySolid(c, ductAssemblyNamed(c, uid));
    });
    shapes.add("ductSegment", [](const Configuration& c, const std::string& uid) {
      const schema::DuctType& duct = ductHolding(c, uid);
      const auto geometry = FuselageGeometry::of(c, duct);
      const auto& uids = geometry->segmentUids();
      return geometry->segmentSolid(static_cast<std::size_t>(std::find(uids.begin(), uids.end(), uid) - uids.begin()));
    });
    shapes.add("fuselageSegment", [](const Configuration& c, const std::string& uid) {
      const std::string& fuselageUid = c.components().named(uid).parentUid;
      const model::ModelComponents& model = model::modelHolding(c, fuselageUid);
      const auto geometry =
          FuselageGeometry::of(c, model::findByUid(c, model, model.fuselages, fuselageUid, "fuselage"));
      const auto& uids = geometry->segmentUids();
      return geometry->segmentSolid(static_cast<std::size_t>(std::find(uids.begin(), uids.end(), uid) - uids.begin()));
    });
  }

  FuselagePlugin()
      : BasicPlugin("fuselage", "0.3.0", "CPACS fuselages (profiles, sections, segments) and ducts lofted as they are",
                    {{"fuselage", "fuselages/fuselage"}, {"fuselageSegment", ""}, {"duct", ""}, {"ductSegment", ""}}) {}

  void registerQueries(query::QueryRegistry& registry) const override {
    registry.add({"fuselage_count", "", "-> number of fuselages of the model",
                  [](Configuration& c, const Json&) -> Json { return model::primaryModel(c).fuselages.size(); }});
    registry.add({"fuselage_uid", "", "fuselage -> uID",
                  [](Configuration& c, const Json& q) -> Json { return selectFuselage(c, q).uID; }});
    registry.add(
        {"fuselage_segment_count", "", "fuselage -> number of segments", [](Configuration& c, const Json& q) -> Json {
           const schema::FuselageType& fuselage = selectFuselage(c, q);
           return fuselage.segments ? fuselage.segments->segment.size() : 0;
         }});
    registry.add({"fuselage_point", "", "fuselage, segment, eta, zeta -> point on the surface",
                  [](Configuration& c, const Json& q) -> Json {
                    const auto geometry = FuselageGeometry::of(c, selectFuselage(c, q));
                    const gp_Pnt p = geometry->point(segmentOf(*geometry, q), query::fractionArgument(q, "eta"),
                                                     query::fractionArgument(q, "zeta"));
                    return Json::array({p.X(), p.Y(), p.Z()});
                  }});
    registry.add({"fuselage_circumference", "", "fuselage, segment, eta -> length of the profile there",
                  [](Configuration& c, const Json& q) -> Json {
                    const auto geometry = FuselageGeometry::of(c, selectFuselage(c, q));
                    return geometry->circumference(segmentOf(*geometry, q), query::fractionArgument(q, "eta"));
                  }});
    registry.add({"fuselage_volume", "", "fuselage -> volume", [](Configuration& c, const Json& q) -> Json {
                    return FuselageGeometry::of(c, selectFuselage(c, q))->volume();
                  }});
    registry.add(
        {"fuselage_surface_area", "", "fuselage -> skin area (no caps)", [](Configuration& c, const Json& q) -> Json {
           return FuselageGeometry::of(c, selectFuselage(c, q))->surfaceArea();
         }});
    registry.add(
        {"fuselage_segment_volume", "", "fuselage, segment -> volume", [](Configuration& c, const Json& q) -> Json {
           const auto geometry = FuselageGeometry::of(c, selectFuselage(c, q));
           return geometry->segmentVolume(segmentOf(*geometry, q));
         }});
    registry.add({"fuselage_segment_surface_area", "", "fuselage, segment -> skin area of the segment",
                  [](Configuration& c, const Json& q) -> Json {
                    const auto geometry = FuselageGeometry::of(c, selectFuselage(c, q));
                    return geometry->segmentSurfaceArea(segmentOf(*geometry, q));
                  }});
  }
};

}  // namespace
}  // namespace airshape::fuselage

AIRSHAPE_PLUGIN(airshape::fuselage::FuselagePlugin)
