// The control-surface plugin: leading- and trailing-edge devices and spoilers of wing
// component segments. It registers its node types; no builder exists yet.
#include "airshape/plugin/basic_plugin.h"

namespace airshape::controlsurfaces {
namespace {

class ControlSurfacesPlugin final : public plugin::BasicPlugin {
 public:
  ControlSurfacesPlugin()
      : BasicPlugin("controlsurfaces", "0.1.0", "flaps, slats, ailerons and spoilers of wings (no builder yet)",
                    {{"trailingEdgeDevice", ""}, {"leadingEdgeDevice", ""}, {"spoiler", ""}},
                    {{"wing", "0.1.0", "1.0.0"}}) {}
};

}  // namespace
}  // namespace airshape::controlsurfaces

AIRSHAPE_PLUGIN(airshape::controlsurfaces::ControlSurfacesPlugin)
