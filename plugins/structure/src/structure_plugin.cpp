// The structure plugin: spars, ribs and cells of wings; frames and stringers of fuselages.
// It registers its node types; no builder exists yet.
#include "airshape/plugin/basic_plugin.h"

namespace airshape::structure {
namespace {

class StructurePlugin final : public plugin::BasicPlugin {
 public:
  StructurePlugin()
      : BasicPlugin("structure", "0.1.0",
                    "wing and fuselage structure: spars, ribs, cells, frames, stringers (no builder yet)",
                    {{"sparSegment", ""}, {"ribsDefinition", ""}, {"cell", ""}, {"frame", ""}, {"stringer", ""}}) {}
};

}  // namespace
}  // namespace airshape::structure

AIRSHAPE_PLUGIN(airshape::structure::StructurePlugin)
