// A third-party plugin that builds on another plugin: it requires the wing plugin and uses
// its public interface (airshape/wing/wing_services.h) for one query op, the leading-edge
// point at the outer end of a component segment.
#include <airshape/configuration.h>
#include <airshape/plugin/basic_plugin.h>
#include <airshape/query/arguments.h>
#include <airshape/wing/wing_services.h>

namespace {

#ifndef REQUIRED_PLUGIN
#define REQUIRED_PLUGIN "wing"
#endif
#ifndef REQUIRED_MINIMUM
#define REQUIRED_MINIMUM "0.1.0"
#endif

class WingTipPlugin final : public airshape::plugin::BasicPlugin {
 public:
  WingTipPlugin()
      : BasicPlugin("wingtip", "0.3.0", "the leading edge at a component segment's tip (a third-party example)", {},
                    {{REQUIRED_PLUGIN, REQUIRED_MINIMUM, "1.0.0"}}) {}

  void useServices(const airshape::plugin::ServiceRegistry& services) override {
    wing_ = services.find<airshape::wing::WingServices>(airshape::wing::kWingServices);
  }

  void registerQueries(airshape::query::QueryRegistry& registry) const override {
    const auto wing = wing_;
    registry.add({"component_segment_tip", "", "component_segment -> [x, y, z]: leading edge at its outer end",
                  [wing](airshape::Configuration& c, const airshape::query::Json& q) {
                    const gp_Pnt tip =
                        wing->componentSegmentPoint(c, airshape::query::stringArgument(q, "component_segment"), 1.0,
                                                    0.0, airshape::wing::WingServices::Surface::Chord);
                    return airshape::query::Json::array({tip.X(), tip.Y(), tip.Z()});
                  }});
  }

 private:
  std::shared_ptr<const airshape::wing::WingServices> wing_;
};

}  // namespace

AIRSHAPE_PLUGIN(WingTipPlugin)
