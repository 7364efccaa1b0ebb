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

class LandingGearPlugin final : public plugin::BasicPlugin {
 public:
  LandingGearPlugin()
      : BasicPlugin("landinggear", "0.1.0", "landing gears: listed, not built yet (their frame is undefined)",
                    {{"landingGear", ""}}) {}

  void registerShapeBuilders(ComponentShapes& shapes) const override { shapes.decline("landingGear", kWhyNotBuilt); }
};

}  // namespace
}  // namespace airshape::landinggear

AIRSHAPE_PLUGIN(airshape::landinggear::LandingGearPlugin)
