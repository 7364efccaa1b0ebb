// A small third-party plugin: a component kind of its own (sensor pods, elements that CPACS
// does not define, at sensorPods/sensorPod in a model) and one query op.
#include <airshape/configuration.h>
#include <airshape/plugin/basic_plugin.h>

namespace {

#ifdef CLAIM_WING
constexpr const char* kNodeType = "wing";
constexpr const char* kPath = "wings/wing";
constexpr const char* kOp = "wing_claimer_op";
#else
constexpr const char* kNodeType = "sensorPod";
constexpr const char* kPath = "sensorPods/sensorPod";
constexpr const char* kOp = "sensor_pod_count";
#endif

class SensorPodPlugin final : public airshape::plugin::BasicPlugin {
 public:
  SensorPodPlugin() : BasicPlugin("sensorpods", "1.2.3", "sensor pods (a third-party example)", {{kNodeType, kPath}}) {}

  void registerQueries(airshape::query::QueryRegistry& registry) const override {
    registry.add({kOp, "", "-> number of sensor pods", [](airshape::Configuration& c, const airshape::query::Json&) {
                    std::size_t count = 0;
                    for (const auto& component : c.components().components())
                      if (component.nodeType == kNodeType) ++count;
                    return airshape::query::Json(count);
                  }});
  }
};

}  // namespace

AIRSHAPE_PLUGIN(SensorPodPlugin)
