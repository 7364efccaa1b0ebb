// The generic-geometry plugin: generic systems and their components, decks and their
// components (seats, galleys, lavatories, ...), built from the geometry of the system or
// deck elements they name (cuboids, cylinders, cones, ellipsoids, tori, multi-segment shapes
// lofted through the fuselage plugin's public interface, and CAD files), and external
// objects (CAD files placed in the aircraft).
#include "airshape/configuration.h"
#include "airshape/plugin/basic_plugin.h"
#include "placed_parts.h"

namespace airshape::generic {
namespace {

/// Systems and decks (groups of their components), their components, and external objects.
std::vector<plugin::NodeType> declaredNodeTypes() {
  using plugin::NodeType;
  std::vector<NodeType> types = {NodeType{"deck", "decks/deck"}.inside("fuselage").asGroup()};
  for (const char* kind :
       {"seatModules/seatModule", "galleys/galley", "lavatories/lavatory", "classDividers/classDivider",
        "genericFloorModules/genericFloorModule", "cargoContainers/cargoContainer", "sidewallPanels/sidewallPanel",
        "luggageCompartments/luggageCompartment", "ceilingPanels/ceilingPanel"})
    types.push_back(NodeType{"deckComponent", kind}.inside("deck").typed("deck_component"));
  types.push_back(NodeType{"genericSystem", "systems/genericSystems/genericSystem"}.typed("generic_system").asGroup());
  types.push_back(
      NodeType{"systemComponent", "components/component"}.inside("genericSystem").typed("system_component"));
  types.push_back(NodeType{"genericGeometryComponent", "genericGeometryComponents/genericGeometryComponent"}
                      .typed("external_object")
                      .inBox());
  return types;
}

class GenericPlugin final : public plugin::BasicPlugin {
 public:
  GenericPlugin()
      : BasicPlugin("generic", "0.2.0", "systems, decks and their components, external objects (CAD files)",
                    declaredNodeTypes(), {{"fuselage", "0.3.0", "1.0.0"}}) {}

  void useServices(const plugin::ServiceRegistry& services) override {
    fuselages_ = services.find<fuselage::FuselageServices>(fuselage::kFuselageServices);
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    const std::shared_ptr<const fuselage::FuselageServices> fuselages = fuselages_;
    shapes.add("systemComponent", [fuselages](const Configuration& c, const std::string& uid) {
      return systemComponentShape(c, *fuselages, uid);
    });
    shapes.add("deckComponent", [fuselages](const Configuration& c, const std::string& uid) {
      return deckComponentShape(c, *fuselages, uid);
    });
    shapes.add("genericSystem", [](const Configuration& c, const std::string& uid) {
      return compoundOfParts(c, uid, "systemComponent");
    });
    shapes.add("deck",
               [](const Configuration& c, const std::string& uid) { return compoundOfParts(c, uid, "deckComponent"); });
    shapes.add("genericGeometryComponent",
               [](const Configuration& c, const std::string& uid) { return externalObjectShape(c, uid); });
  }

 private:
  std::shared_ptr<const fuselage::FuselageServices> fuselages_;
};

}  // namespace
}  // namespace airshape::generic

AIRSHAPE_PLUGIN(airshape::generic::GenericPlugin)
