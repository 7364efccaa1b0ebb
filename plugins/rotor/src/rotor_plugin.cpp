// The rotor plugin: rotors of rotorcraft models with their hubs and attached blades (the blades
// themselves are wings, built by the wing plugin). It claims its node type; no builder exists yet.
#include "airshape/plugin/basic_plugin.h"

namespace airshape::rotor {
namespace {

class RotorPlugin final : public plugin::BasicPlugin {
 public:
  RotorPlugin()
      : BasicPlugin("rotor", "0.1.0", "rotors with their attached blades (no builder yet)", {{"rotor", ""}}) {}
};

}  // namespace
}  // namespace airshape::rotor

AIRSHAPE_PLUGIN(airshape::rotor::RotorPlugin)
