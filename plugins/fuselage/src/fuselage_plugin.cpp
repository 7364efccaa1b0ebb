// The fuselage plugin: CPACS fuselages. It answers the fuselage ops that need no
// geometry; the geometry ops are registered as pending until the fuselage builder exists.
#include "airshape/configuration.h"
#include "airshape/model/primary_model.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/query/arguments.h"

namespace airshape::fuselage {

using query::Json;

namespace {

schema::FuselageType& selectFuselage(const Configuration& configuration, const Json& query) {
  const auto& fuselages = model::primaryModel(configuration).fuselages;
  return *fuselages[query::selectByIndexOrUid(query, "fuselage", model::uidsOf(fuselages), "fuselage")];
}

class FuselagePlugin final : public plugin::BasicPlugin {
 public:
  FuselagePlugin()
      : BasicPlugin("fuselage", "0.1.0", "CPACS fuselages: profiles, sections, segments",
                    {{"fuselage", "fuselages/fuselage"}}) {}

  void registerQueries(query::QueryRegistry& registry) const override {
    registry.add(
        {"fuselage_count", "", "-> number of fuselages of the model",
         [](Configuration& c, const Json&) -> Json { return model::primaryModel(c).fuselages.size(); }});
    registry.add({"fuselage_uid", "", "fuselage -> uID",
                  [](Configuration& c, const Json& q) -> Json { return selectFuselage(c, q).uID; }});
    registry.add(
        {"fuselage_segment_count", "", "fuselage -> number of segments", [](Configuration& c, const Json& q) -> Json {
           const schema::FuselageType& fuselage = selectFuselage(c, q);
           return fuselage.segments ? fuselage.segments->segment.size() : 0;
         }});
    plugin::registerPendingOps(registry, "fuselage",
                               {{"fuselage_point", "fuselage, segment, eta, zeta -> point on the surface"},
                                {"fuselage_volume", "fuselage -> volume"},
                                {"fuselage_surface_area", "fuselage -> skin area"},
                                {"fuselage_segment_volume", "fuselage, segment -> volume"},
                                {"fuselage_segment_surface_area", "fuselage, segment -> skin area"},
                                {"fuselage_circumference", "fuselage, segment, eta -> circumference"}});
  }
};

}  // namespace
}  // namespace airshape::fuselage

AIRSHAPE_PLUGIN(airshape::fuselage::FuselagePlugin)
