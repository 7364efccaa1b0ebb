// The generic-geometry plugin: wing fuel tanks, decks and deck components, generic systems and
// their components, and external objects (CAD files placed in the aircraft). Ducts are lofted
// as fuselages are, by the fuselage plugin; tanks are the tank plugin's. It claims the node types of the component
// catalogue (graph/component_graph.h); no builder exists yet. Landing gear is left to a plugin of its own (the
// third-party example of tests/third_party_plugin is one).
#include "airshape/plugin/basic_plugin.h"

namespace airshape::generic {
namespace {

class GenericPlugin final : public plugin::BasicPlugin {
 public:
  GenericPlugin()
      : BasicPlugin("generic", "0.1.0", "wing fuel tanks, decks, systems and external objects (no builder yet)",
                    {{"wingFuelTank", ""},
                     {"deck", ""},
                     {"deckComponent", ""},
                     {"genericSystem", ""},
                     {"systemComponent", ""},
                     {"genericGeometryComponent", ""}}) {}
};

}  // namespace
}  // namespace airshape::generic

AIRSHAPE_PLUGIN(airshape::generic::GenericPlugin)
