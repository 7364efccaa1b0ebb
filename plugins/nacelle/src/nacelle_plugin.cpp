// The nacelle plugin: engines placed on the aircraft (with their nacelles) and pylons.
// It registers its node types; no builder exists yet.
#include "airshape/plugin/basic_plugin.h"

namespace airshape::nacelle {
namespace {

class NacellePlugin final : public plugin::BasicPlugin {
 public:
  NacellePlugin()
      : BasicPlugin("nacelle", "0.1.0", "engine nacelles and pylons (no builder yet)",
                    {{"engine", ""}, {"enginePylon", ""}, {"pylonSegment", ""}}) {}
};

}  // namespace
}  // namespace airshape::nacelle

AIRSHAPE_PLUGIN(airshape::nacelle::NacellePlugin)
