// A small third-party plugin: landing gears as a component type, and one query op.
#include <airshape/configuration.h>
#include <airshape/plugin/basic_plugin.h>

namespace {

#ifdef CLAIM_WING
constexpr const char* kNodeType = "wing";
constexpr const char* kOp = "wing_claimer_op";
#else
constexpr const char* kNodeType = "landingGear";
constexpr const char* kOp = "landing_gear_count";
#endif

class LandingGearPlugin final : public airshape::plugin::BasicPlugin {
 public:
  LandingGearPlugin()
      : BasicPlugin("landinggear", "1.2.3", "landing gears (a third-party example)",
                    {{kNodeType, "landingGears/landingGear"}}) {}

  void registerQueries(airshape::query::QueryRegistry& registry) const override {
    registry.add({kOp, "", "-> number of landing gears", [](airshape::Configuration& c, const airshape::query::Json&) {
                    std::size_t count = 0;
                    for (const auto& component : c.components().components())
                      if (component.nodeType == "landingGear") ++count;
                    return airshape::query::Json(count);
                  }});
  }
};

}  // namespace

AIRSHAPE_PLUGIN(LandingGearPlugin)
