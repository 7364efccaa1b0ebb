// The landing-gear plugin: it claims the landing gears of aircraft and rotorcraft and, for now,
// leaves them unbuilt on purpose, saying why (docs/landinggear.md): the schema gives a gear's
// struts no frame to place them in, and its lengths are metres while the only public example
// writes millimetres, so any solid built today would rest on a guess.
#include "airshape/plugin/basic_plugin.h"

namespace airshape::landinggear {
namespace {

constexpr const char* kWhyNotBuilt =
    "CPACS 3.5 gives its struts no frame, and its one public example is in millimetres, not metres "
    "(docs/landinggear.md)";

/// An aircraft's gears, and a rotorcraft's kind by kind (CPACS 3.5 rotorcraftModelType). The
/// reference library has no component for them.
std::vector<plugin::NodeType> declaredNodeTypes() {
  std::vector<plugin::NodeType> types;
  for (const char* path : {"landingGears/landingGear", "landingGear/noseGears/noseGear",
                           "landingGear/mainGears/mainGear", "landingGear/skidGears/skidGear"})
    types.push_back(plugin::NodeType{"landingGear", path}.typed("landing_gear").unlisted());
  return types;
}

class LandingGearPlugin final : public plugin::BasicPlugin {
 public:
  LandingGearPlugin()
      : BasicPlugin("landinggear", "0.1.0", "landing gears: listed, not built yet (their frame is undefined)",
                    declaredNodeTypes()) {}

  void registerShapeBuilders(ComponentShapes& shapes) const override { shapes.decline("landingGear", kWhyNotBuilt); }
};

}  // namespace
}  // namespace airshape::landinggear

AIRSHAPE_PLUGIN(airshape::landinggear::LandingGearPlugin)
