// The structure plugin: spars, ribs and cells of wings; frames, stringers, bulkheads, doors,
// floor beams and walls of fuselages. It builds on the wing plugin's public interface
// (airshape/wing/wing_services.h), on the control-surfaces plugin's for the structure of flaps, slats
// and spoilers (airshape/controlsurfaces/device_services.h), on the fuselages' component shapes and, for walls in tank
// vessels, on the tank plugin's public interface (airshape/tank/tank_services.h). Spar webs, ribs,
// cells, wing fuel tanks, frames and stringers (as lines), pressure bulkheads, doors, walls and cross beams are built;
// the other node types are claimed (graph/component_graph.h) and wait for their builders.
#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/wing/wing_services.h"
#include "cell_list.h"
#include "cell_skin.h"
#include "cross_beam.h"
#include "fuselage_door.h"
#include "fuselage_wall.h"
#include "pressure_bulkhead.h"
#include "profile_sweep.h"
#include "rib_faces.h"
#include "rib_list.h"
#include "skin_lines.h"
#include "spar_list.h"
#include "spar_web.h"
#include "wing_fuel_tank.h"
#include "wing_fuel_tank_list.h"

namespace airshape::structure {
namespace {

/// The services the wing structure builders hold: the wing's, and the control devices'.
struct HeldServices {
  std::shared_ptr<const wing::WingServices> wing;
  std::shared_ptr<const controlsurfaces::DeviceServices> devices;

  StructureServices operator*() const { return {*wing, *devices}; }
};

/// Structure lies inside its parent's solid (exported when named, not in the configuration's
/// box). A wing's: spars, ribs and cells in its component segments and in their control devices,
/// and its fuel tanks. A body's skin stiffening (a fuselage's, a tank vessel's): frames,
/// stringers, walls; and a fuselage's further structure. The reference library has no component
/// for wing fuel tanks, frames, stringers, floor panels, windows, intercostals and general
/// structural members: built, but not listed.
std::vector<plugin::NodeType> declaredNodeTypes() {
  using plugin::NodeType;
  std::vector<NodeType> types;
  for (const char* holder : {"wingComponentSegment", "trailingEdgeDevice", "leadingEdgeDevice", "spoiler"}) {
    types.push_back(NodeType{"sparSegment", "structure/spars/sparSegments/sparSegment"}
                        .inside(holder)
                        .typed("wing_spar")
                        .asStructure());
    types.push_back(NodeType{"ribsDefinition", "structure/ribsDefinitions/ribsDefinition"}
                        .inside(holder)
                        .typed("wing_rib")
                        .asStructure());
    for (const char* shell : {"structure/upperShell/cells/cell", "structure/lowerShell/cells/cell"})
      types.push_back(NodeType{"wingCell", shell}.inside(holder).typed("wing_cell").asInsideParent());
  }
  types.push_back(NodeType{"wingFuelTank", "wingFuelTanks/wingFuelTank"}
                      .inside("wingComponentSegment")
                      .typed("tank")
                      .asInsideParent()
                      .unlisted());
  for (const char* body : {"fuselage", "tankHull"}) {
    types.push_back(NodeType{"frame", "structure/frames/frame"}.inside(body).asStructure().unlisted());
    types.push_back(NodeType{"stringer", "structure/stringers/stringer"}.inside(body).asStructure().unlisted());
    types.push_back(NodeType{"wallSegment", "structure/walls/wallSegments/wallSegment"}
                        .inside(body)
                        .typed("fuselage_wall")
                        .asStructure());
  }
  const std::vector<NodeType> inFuselageStructure = {
      NodeType{"pressureBulkhead", "pressureBulkheads/pressureBulkhead"}.typed("pressure_bulkhead"),
      NodeType{"door", "cargoDoors/cargoDoor"}.typed("cargo_door"),
      NodeType{"door", "paxDoors/paxDoor"}.typed("cargo_door"),
      // the reference's type for cross beams
      NodeType{"crossBeam", "paxCrossBeams/paxCrossBeam"}.typed("generic_system"),
      NodeType{"crossBeam", "cargoCrossBeams/cargoCrossBeam"}.typed("generic_system"),
      NodeType{"crossBeamStrut", "paxCrossBeamStruts/paxCrossBeamStrut"}.typed("cross_beam_strut"),
      NodeType{"crossBeamStrut", "cargoCrossBeamStruts/cargoCrossBeamStrut"}.typed("cross_beam_strut"),
      NodeType{"longFloorBeam", "longFloorBeams/longFloorBeam"}.typed("long_floor_beam"),
      NodeType{"floorPanel", "floorPanels/floorPanel"}.typed("floor_panel").unlisted(),
      NodeType{"window", "windows/window"}.unlisted(),
      NodeType{"intercostal", "intercostals/intercostal"}.unlisted(),
      NodeType{"structuralMember", "generalStructuralMembers/generalStructuralMember"}
          .typed("structural_member")
          .unlisted(),
  };
  for (NodeType type : inFuselageStructure) {
    type.pathInModel = "structure/" + type.pathInModel;
    types.push_back(type.inside("fuselage").asStructure());
  }
  return types;
}

class StructurePlugin final : public plugin::BasicPlugin {
 public:
  StructurePlugin()
      : BasicPlugin(
            "structure", "0.7.0",
            "wing and fuselage structure: spar webs, ribs, cells, wing fuel tanks, frames and stringers (lines), "
            "pressure bulkheads, doors, walls, cross beams, struts and long floor beams",
            declaredNodeTypes(),
            {{"wing", "0.1.0", "1.0.0"},
             {"fuselage", "0.1.0", "1.0.0"},
             {"tank", "0.2.0", "1.0.0"},
             {"controlsurfaces", "0.3.0", "1.0.0"}}) {}

  void useServices(const plugin::ServiceRegistry& services) override {
    wing_.wing = services.find<wing::WingServices>(wing::kWingServices);
    wing_.devices = services.find<controlsurfaces::DeviceServices>(controlsurfaces::kDeviceServices);
    tanks_ = services.find<tank::TankServices>(tank::kTankServices);
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    const HeldServices wing = wing_;
    shapes.add("sparSegment", [wing](const Configuration& c, const std::string& uid) {
      return sparWeb(c, *wing, sparSegmentNamed(c, uid));
    });
    shapes.add("ribsDefinition", [wing](const Configuration& c, const std::string& uid) {
      return ribFaces(c, *wing, ribsDefinitionNamed(c, uid));
    });
    shapes.add("wingCell", [wing](const Configuration& c, const std::string& uid) {
      return cellSkin(c, *wing, wingCellNamed(c, uid));
    });
    shapes.add("wingFuelTank", [wing](const Configuration& c, const std::string& uid) {
      return wingFuelTankSolid(c, *wing, wingFuelTankNamed(c, uid));
    });
    shapes.add("pressureBulkhead",
               [](const Configuration& c, const std::string& uid) { return pressureBulkhead(c, uid); });
    shapes.add("door", [](const Configuration& c, const std::string& uid) { return fuselageDoor(c, uid); });
    shapes.add("crossBeam", [](const Configuration& c, const std::string& uid) { return crossBeam(c, uid); });
    shapes.add("longFloorBeam", [](const Configuration& c, const std::string& uid) { return longFloorBeam(c, uid); });
    shapes.add("crossBeamStrut", [](const Configuration& c, const std::string& uid) { return crossBeamStrut(c, uid); });
    const std::shared_ptr<const tank::TankServices> tanks = tanks_;
    shapes.add("frame",
               [tanks](const Configuration& c, const std::string& uid) { return frameLine(c, tanks.get(), uid); });
    shapes.add("stringer",
               [tanks](const Configuration& c, const std::string& uid) { return stringerLine(c, tanks.get(), uid); });
    shapes.addDetailed(
        "frame", [tanks](const Configuration& c, const std::string& uid) { return frameProfile(c, tanks.get(), uid); });
    shapes.addDetailed("stringer", [tanks](const Configuration& c, const std::string& uid) {
      return stringerProfile(c, tanks.get(), uid);
    });
    shapes.add("wallSegment",
               [tanks](const Configuration& c, const std::string& uid) { return fuselageWall(c, tanks.get(), uid); });
  }

 private:
  HeldServices wing_;
  std::shared_ptr<const tank::TankServices> tanks_;
};

}  // namespace
}  // namespace airshape::structure

AIRSHAPE_PLUGIN(airshape::structure::StructurePlugin)
