// The structure plugin: spars, ribs and cells of wings; frames and stringers of fuselages.
// It claims the node types of the component catalogue (graph/component_graph.h); no builder
// exists yet.
#include "airshape/plugin/basic_plugin.h"

namespace airshape::structure {
namespace {

class StructurePlugin final : public plugin::BasicPlugin {
 public:
  StructurePlugin()
      : BasicPlugin("structure", "0.1.0",
                    "wing and fuselage structure: spars, ribs, cells, frames, stringers, bulkheads, doors, "
                    "floor beams, walls (no builder yet)",
                    {{"sparSegment", ""},
                     {"ribsDefinition", ""},
                     {"wingCell", ""},
                     {"frame", ""},
                     {"stringer", ""},
                     {"pressureBulkhead", ""},
                     {"door", ""},
                     {"crossBeam", ""},
                     {"crossBeamStrut", ""},
                     {"longFloorBeam", ""},
                     {"wallSegment", ""},
                     {"floorPanel", ""},
                     {"window", ""},
                     {"intercostal", ""},
                     {"structuralMember", ""}},
                    {{"wing", "0.1.0", "1.0.0"}, {"fuselage", "0.1.0", "1.0.0"}}) {}
};

}  // namespace
}  // namespace airshape::structure

AIRSHAPE_PLUGIN(airshape::structure::StructurePlugin)
