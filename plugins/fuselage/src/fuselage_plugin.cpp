// The fuselage plugin: CPACS fuselages and ducts, lofted from their sections of fuselage
// profiles, and the fuselage ops. It offers the same loft to other plugins (tank vessels)
// through its public interface (airshape/fuselage/fuselage_services.h).
#include <algorithm>
#include <set>

#include <gp_Trsf.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/fused_shape.h"
#include "airshape/fuselage/fuselage_list.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/model/segment_chain.h"
#include "airshape/model/symmetry.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/query/arguments.h"
#include "airshape/query/model_selection.h"
#include "ducts.h"
#include "fuselage_geometry.h"
#include "fuselage_services.h"

namespace airshape::fuselage {

using query::Json;

namespace {

/// The fuselage a query names by index or uID, in the model queries address (the first one).
schema::FuselageType& selectFuselage(const Configuration& configuration, const Json& query) {
  return query::selectInFirstModel(configuration, fuselagesOf(configuration), fuselageNodeTypes(), query, "fuselage",
                                   "fuselage");
}

/// The skin area of a fuselage with cut-outs: every face of the cut solid but the fuselage's
/// own caps and symmetry faces, so the walls the cut-outs leave count as skin.
double skinAreaWithCutOuts(const NamedShape& cut, const NamedShape& clean) {
  std::set<std::string> notSkin;
  const std::string skin = "/skin";
  for (const auto& [name, face] : clean.faces)
    if (name.size() < skin.size() || name.compare(name.size() - skin.size(), skin.size(), skin) != 0)
      notSkin.insert(name);
  double area = 0.0;
  for (const auto& [name, face] : cut.faces)
    if (notSkin.count(name) == 0) area += geometry::areaOf(face);
  return area;
}

std::size_t segmentOf(const FuselageGeometry& geometry, const Json& q) {
  return query::selectByIndexOrUid(q, "segment", geometry.segmentUids(), "segment");
}

/// Fuselages with their segments (parts of the fuselage's solid), and ducts lofted the same way;
/// a duct assembly is a group of ducts.
std::vector<plugin::NodeType> declaredNodeTypes() {
  using plugin::NodeType;
  return {NodeType{"fuselage", "fuselages/fuselage"}.inBox().placedByItsTransformation().leftOutWhen(
              model::segmentsFormNoChain<schema::FuselageType>),
          NodeType{"fuselageSegment", "segments/segment"}.inside("fuselage").typed("fuselage_segment").asPart(),
          NodeType{"duct", "ducts/duct"}.placedByItsTransformation(), NodeType{"duct", "ducts/ductAssembly"}.asGroup(),
          NodeType{"ductSegment", "ducts/duct/segments/segment"}.typed("fuselage_segment").asPart()};
}

class FuselagePlugin final : public plugin::BasicPlugin {
 public:
  void offerServices(plugin::ServiceRegistry& services) const override {
    services.offer<FuselageServices>(kFuselageServices, makeFuselageServices());
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    shapes.addCutOuts({kDuctCutOuts,
                       "the duct assemblies cut out of the wings and fuselages they pass through "
                       "(off by default, as in the reference library)",
                       ductCutOutsOf});
    shapes.add("fuselage", [](const Configuration& c, const std::string& uid) {
      return FuselageGeometry::of(c, fuselageNamed(c, uid))->solid(uid);
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
      const auto geometry = FuselageGeometry::of(c, fuselageNamed(c, fuselageUid));
      const auto& uids = geometry->segmentUids();
      return geometry->segmentSolid(static_cast<std::size_t>(std::find(uids.begin(), uids.end(), uid) - uids.begin()));
    });
  }

  FuselagePlugin()
      : BasicPlugin("fuselage", "0.3.0", "CPACS fuselages (profiles, sections, segments) and ducts lofted as they are",
                    declaredNodeTypes()) {}

  void registerQueries(query::QueryRegistry& registry) const override {
    registry.add({"fuselage_count", "", "-> number of fuselages of the model",
                  [](Configuration& c, const Json&) -> Json { return fuselagesOf(c).size(); }});
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
    registry.add({"fuselage_volume", "", "fuselage -> volume (with its duct cut-outs when they are on)",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::FuselageType& fuselage = selectFuselage(c, q);
                    if (c.shapes().isCutByOthers(c, fuselage.uID))
                      return geometry::enclosedVolume(c.shapes().shapeOf(c, fuselage.uID));
                    return FuselageGeometry::of(c, fuselage)->volume();
                  }});
    registry.add({"fuselage_surface_area", "",
                  "fuselage -> skin area (no caps; with the walls of its duct cut-outs when they are on)",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::FuselageType& fuselage = selectFuselage(c, q);
                    if (c.shapes().isCutByOthers(c, fuselage.uID))
                      return skinAreaWithCutOuts(c.shapes().namedShapeOf(c, fuselage.uID),
                                                 c.shapes().cleanNamedShapeOf(c, fuselage.uID));
                    return FuselageGeometry::of(c, fuselage)->surfaceArea();
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
