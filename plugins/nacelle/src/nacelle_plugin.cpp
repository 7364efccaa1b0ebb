// The nacelle plugin: engines placed on the aircraft (with their nacelles) and engine pylons.
// It builds on the wing plugin's public interface (airshape/wing/wing_services.h) for the
// pylons' airfoils. Pylons, their segments and nacelles of one-section cowls are built.
#include "airshape/configuration.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/wing/wing_services.h"
#include "engine_nacelle.h"
#include "pylon_loft.h"

namespace airshape::nacelle {
namespace {

/// Engines (with their nacelles) and pylons with their segments (parts of the pylon's solid).
std::vector<plugin::NodeType> declaredNodeTypes() {
  using plugin::NodeType;
  return {NodeType{"engine", "engines/engine"}.typed("engine_nacelle").placedByItsTransformation(),
          NodeType{"enginePylon", "enginePylons/enginePylon"}.typed("engine_pylon").inBox().placedByItsTransformation(),
          NodeType{"pylonSegment", "segments/segment"}.inside("enginePylon").typed("wing_segment").asPart()};
}

class NacellePlugin final : public plugin::BasicPlugin {
 public:
  NacellePlugin()
      : BasicPlugin("nacelle", "0.2.0", "engine nacelles (cowls of one section) and pylons with their segments",
                    declaredNodeTypes(), {{"wing", "0.1.0", "1.0.0"}}) {}

  void useServices(const plugin::ServiceRegistry& services) override {
    wing_ = services.find<wing::WingServices>(wing::kWingServices);
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    const std::shared_ptr<const wing::WingServices> wing = wing_;
    shapes.add("engine", [](const Configuration& c, const std::string& uid) { return engineNacelle(c, uid); });
    shapes.add("enginePylon", [wing](const Configuration& c, const std::string& uid) {
      return PylonLoft::of(c, *wing, uid)->solid();
    });
    shapes.add("pylonSegment", [wing](const Configuration& c, const std::string& uid) {
      return PylonLoft::of(c, *wing, pylonHoldingSegment(c, uid))->segmentSolid(uid);
    });
  }

 private:
  std::shared_ptr<const wing::WingServices> wing_;
};

}  // namespace
}  // namespace airshape::nacelle

AIRSHAPE_PLUGIN(airshape::nacelle::NacellePlugin)
