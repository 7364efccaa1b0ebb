#include "airshape/graph/component_graph.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/depth_first_search.hpp>
#include <boost/graph/strong_components.hpp>
#include <xercesc/dom/DOM.hpp>

#include "airshape/error.h"
#include "airshape/xml/text.h"

namespace airshape::graph {

using namespace xercesc;

namespace {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;

std::vector<std::string> split(const std::string& path) {
  std::vector<std::string> steps;
  std::stringstream stream(path);
  for (std::string step; std::getline(stream, step, '/');)
    if (!step.empty()) steps.push_back(step);
  return steps;
}

/// Elements reached from `from` by following the steps of a relative path.
void select(const DOMElement& from, const std::vector<std::string>& steps, std::size_t step,
            std::vector<const DOMElement*>& found) {
  if (step == steps.size()) {
    found.push_back(&from);
    return;
  }
  for (const DOMElement* child = xml::firstElement(from); child != nullptr; child = xml::nextElement(*child))
    if (xml::equalsAscii(child->getTagName(), steps[step].c_str())) select(*child, steps, step + 1, found);
}

std::vector<const DOMElement*> models(const DOMElement& root) {
  std::vector<const DOMElement*> found;
  select(root, {"vehicles", "aircraft", "model"}, 0, found);
  select(root, {"vehicles", "rotorcraft", "model"}, 0, found);
  return found;
}

/// Records vertices in the order a depth-first search discovers them.
class DiscoveryRecorder : public boost::default_dfs_visitor {
 public:
  explicit DiscoveryRecorder(std::vector<std::size_t>& order) : order_(order) {}
  void discover_vertex(Graph::vertex_descriptor v, const Graph&) { order_.push_back(v); }

 private:
  std::vector<std::size_t>& order_;
};

/// The elements inside a wing (or rotor blade) that are geometry of their own.
void addWingContents(const std::string& wing, std::vector<ComponentLocation>& locations) {
  locations.push_back({"wingSegment", wing + "/segments/segment", "wing_segment", true});
  const std::string segment = wing + "/componentSegments/componentSegment";
  locations.push_back({"wingComponentSegment", segment, "wing_component_segment", true});
  const auto addStructure = [&](const std::string& structure) {
    // Structure lies inside its wing: exported when named, not part of the configuration box.
    locations.push_back({"sparSegment", structure + "/spars/sparSegments/sparSegment", "wing_spar", false, true, true});
    locations.push_back(
        {"ribsDefinition", structure + "/ribsDefinitions/ribsDefinition", "wing_rib", false, true, true});
    locations.push_back({"wingCell", structure + "/upperShell/cells/cell", "wing_cell", false, true});
    locations.push_back({"wingCell", structure + "/lowerShell/cells/cell", "wing_cell", false, true});
  };
  addStructure(segment + "/structure");
  // A wing fuel tank is a part of the wing's volume: exported when named, like structure.
  locations.push_back({"wingFuelTank", segment + "/wingFuelTanks/wingFuelTank", "tank", false, true});
  for (const auto& [device, folder] : {std::pair<std::string, std::string>{"trailingEdgeDevice", "trailingEdgeDevices"},
                                       {"leadingEdgeDevice", "leadingEdgeDevices"},
                                       {"spoiler", "spoilers"}}) {
    const std::string path = segment + "/controlSurfaces/" + folder + "/" + device;
    locations.push_back({device, path, "control_surface", false, true});
    addStructure(path + "/structure");
  }
}

/// The stiffening of a body's skin (a fuselage's, a tank vessel's): frames, stringers, walls.
void addBodyStructure(const std::string& structure, std::vector<ComponentLocation>& locations) {
  locations.push_back({"frame", structure + "/frames/frame", "frame", false, true, true});
  locations.push_back({"stringer", structure + "/stringers/stringer", "stringer", false, true, true});
  locations.push_back(
      {"wallSegment", structure + "/walls/wallSegments/wallSegment", "fuselage_wall", false, true, true});
}

/// The elements inside a fuselage that are geometry of their own: structure, decks, tanks.
void addFuselageContents(const std::string& fuselage, std::vector<ComponentLocation>& locations) {
  locations.push_back({"fuselageSegment", fuselage + "/segments/segment", "fuselage_segment", true});
  const std::string structure = fuselage + "/structure";
  addBodyStructure(structure, locations);
  const std::vector<ComponentLocation> inStructure = {
      {"pressureBulkhead", "pressureBulkheads/pressureBulkhead", "pressure_bulkhead"},
      {"door", "cargoDoors/cargoDoor", "cargo_door"},
      {"door", "paxDoors/paxDoor", "cargo_door"},
      {"crossBeam", "paxCrossBeams/paxCrossBeam", "generic_system"},  // the reference's type for cross beams
      {"crossBeam", "cargoCrossBeams/cargoCrossBeam", "generic_system"},
      {"crossBeamStrut", "paxCrossBeamStruts/paxCrossBeamStrut", "cross_beam_strut"},
      {"crossBeamStrut", "cargoCrossBeamStruts/cargoCrossBeamStrut", "cross_beam_strut"},
      {"longFloorBeam", "longFloorBeams/longFloorBeam", "long_floor_beam"},
      {"floorPanel", "floorPanels/floorPanel", "floor_panel"},
      {"window", "windows/window", "window"},
      {"intercostal", "intercostals/intercostal", "intercostal"},
      {"structuralMember", "generalStructuralMembers/generalStructuralMember", "structural_member"},
  };
  for (const ComponentLocation& location : inStructure)
    locations.push_back(
        {location.nodeType, structure + "/" + location.pathInModel, location.typeName, false, true, true});
  const std::string deck = fuselage + "/decks/deck";
  locations.push_back({"deck", deck, "deck"});
  for (const char* kind :
       {"seatModules/seatModule", "galleys/galley", "lavatories/lavatory", "classDividers/classDivider",
        "genericFloorModules/genericFloorModule", "cargoContainers/cargoContainer", "sidewallPanels/sidewallPanel",
        "luggageCompartments/luggageCompartment", "ceilingPanels/ceilingPanel"})
    locations.push_back({"deckComponent", deck + "/" + kind, "deck_component"});
  const std::string tanks = fuselage + "/fuelTanks/";
  locations.push_back({"fuelTank", tanks + "genericFuelTanks/genericFuelTank", "tank"});
  locations.push_back({"tankHull", tanks + "genericFuelTanks/genericFuelTank/hulls/hull", "tank_hull"});
  locations.push_back({"hullSegment", tanks + "genericFuelTanks/genericFuelTank/hulls/hull/segments/segment",
                       "fuselage_segment", true});
  locations.push_back({"fuelTank", tanks + "integralFuelTanks/integralFuelTank", "tank"});
}

/// Tanks of the model itself, with their vessels (a layout newer than CPACS 3.5's schema that
/// real files and the reference use: model/fuelTanks/fuelTank/vessels/vessel).
void addModelTanks(std::vector<ComponentLocation>& locations) {
  locations.push_back({"fuelTank", "fuelTanks/fuelTank", "tank"});
  locations.push_back({"tankHull", "fuelTanks/fuelTank/vessels/vessel", "tank_hull"});
  locations.push_back({"hullSegment", "fuelTanks/fuelTank/vessels/vessel/segments/segment", "fuselage_segment", true});
  addBodyStructure("fuelTanks/fuelTank/vessels/vessel/structure", locations);
}

/// Whether the reference library registers components of this location (QUERY-components §1):
/// it has no class for spoilers, wing fuel tanks, frames, stringers, floor panels, windows,
/// intercostals, general structural members and landing gear (nor for what lies in a
/// spoiler), and reads tanks only in the model's own fuelTanks (not the CPACS 3.5 layout
/// inside fuselages).
bool referenceRegisters(const ComponentLocation& location) {
  static const std::set<std::string> unregistered = {"spoiler",     "wingFuelTank",     "frame",
                                                     "stringer",    "floorPanel",       "window",
                                                     "intercostal", "structuralMember", "landingGear"};
  const bool inFuselageTanks = location.pathInModel.rfind("fuselages/fuselage/fuelTanks/", 0) == 0;
  const bool inSpoiler = location.pathInModel.find("/spoilers/spoiler/") != std::string::npos;
  return unregistered.count(location.nodeType) == 0 && !inFuselageTanks && !inSpoiler;
}

std::vector<ComponentLocation> catalogue() {
  std::vector<ComponentLocation> locations = {
      {kModelNodeType, "", "plane", true},
      {"fuselage", "fuselages/fuselage", "fuselage"},
      {"wing", "wings/wing", "wing"},
      {"rotorBlade", "rotorBlades/rotorBlade", "rotor_blade"},
      {"engine", "engines/engine", "engine_nacelle"},
      {"enginePylon", "enginePylons/enginePylon", "engine_pylon"},
      {"pylonSegment", "enginePylons/enginePylon/segments/segment", "wing_segment", true},
      {"rotor", "rotors/rotor", "rotor"},
      {"duct", "ducts/duct", "duct"},
      {"duct", "ducts/ductAssembly", "duct"},
      {"ductSegment", "ducts/duct/segments/segment", "fuselage_segment", true},
      {"genericGeometryComponent", "genericGeometryComponents/genericGeometryComponent", "external_object"},
      {"landingGear", "landingGears/landingGear", "landing_gear"},
      // A rotorcraft's gears (CPACS 3.5 rotorcraftModelType), kind by kind.
      {"landingGear", "landingGear/noseGears/noseGear", "landing_gear"},
      {"landingGear", "landingGear/mainGears/mainGear", "landing_gear"},
      {"landingGear", "landingGear/skidGears/skidGear", "landing_gear"},
      {"genericSystem", "systems/genericSystems/genericSystem", "generic_system"},
      {"systemComponent", "systems/genericSystems/genericSystem/components/component", "system_component"},
  };
  addWingContents("wings/wing", locations);
  addWingContents("rotorBlades/rotorBlade", locations);
  addFuselageContents("fuselages/fuselage", locations);
  addModelTanks(locations);
  for (ComponentLocation& location : locations) {
    location.listed = referenceRegisters(location);
    location.group = location.nodeType == "genericSystem" || location.nodeType == "deck" ||
                     location.pathInModel == "ducts/ductAssembly";
    location.inConfigurationBox = location.pathInModel == "fuselages/fuselage" ||
                                  location.pathInModel == "wings/wing" || location.pathInModel == "rotors/rotor" ||
                                  location.pathInModel == "enginePylons/enginePylon" ||
                                  location.pathInModel == "genericGeometryComponents/genericGeometryComponent";
  }
  return locations;
}

}  // namespace

const std::vector<ComponentLocation>& standardComponentLocations() {
  static const std::vector<ComponentLocation> locations = catalogue();
  return locations;
}

long ComponentGraph::find(const std::string& uid) const {
  const auto entry = byUid_.find(uid);
  return entry == byUid_.end() || uid.empty() ? -1 : static_cast<long>(entry->second);
}

const Component& ComponentGraph::named(const std::string& uid) const {
  const long index = find(uid);
  if (index < 0) throw Error(ErrorCode::InvalidArgument, "no component with uID '" + uid + "'");
  return components_[static_cast<std::size_t>(index)];
}

void ComponentGraph::add(const DOMElement& element, const ComponentLocation& location, std::size_t model) {
  Component component;
  component.uid = xml::attribute(element, "uID");
  if (!component.uid.empty() && !byUid_.emplace(component.uid, components_.size()).second)
    return;  // a repeated uID: the first definition wins
  component.nodeType = location.nodeType;
  component.typeName = location.typeName;
  component.part = location.part;
  component.insideParent = location.insideParent;
  component.structure = location.structure;
  component.inConfigurationBox = location.inConfigurationBox;
  component.listed = location.listed;
  component.group = location.group;
  if (const DOMElement* parent = xml::firstChild(element, "parentUID")) component.parentUid = xml::text(*parent);
  component.parentUid.erase(0, component.parentUid.find_first_not_of(" \t\r\n"));
  component.parentUid.erase(component.parentUid.find_last_not_of(" \t\r\n") + 1);
  component.xpath = xml::pathOf(element);
  component.model = model;
  component.element = &element;
  components_.push_back(std::move(component));
}

void ComponentGraph::resolveParents(Problems& warnings) {
  std::unordered_map<const DOMNode*, std::size_t> byElement;
  for (std::size_t i = 0; i < components_.size(); ++i) byElement.emplace(components_[i].element, i);
  for (Component& component : components_) {
    const Component* enclosing = nullptr;
    bool parentUidNamesAnEnclosingElement = false;
    for (const DOMNode* above = component.element->getParentNode();
         above != nullptr && above->getNodeType() == DOMNode::ELEMENT_NODE; above = above->getParentNode()) {
      const auto& element = static_cast<const DOMElement&>(*above);
      if (!component.parentUid.empty() && xml::attribute(element, "uID") == component.parentUid)
        parentUidNamesAnEnclosingElement = true;
      const auto found = byElement.find(above);
      if (found != byElement.end() && enclosing == nullptr && components_[found->second].nodeType != kModelNodeType)
        enclosing = &components_[found->second];  // everything lies in its model, which is no parent
    }
    if (!component.parentUid.empty() && find(component.parentUid) >= 0) continue;
    if (!component.parentUid.empty() && !parentUidNamesAnEnclosingElement)
      warnings.push_back({Problem::Severity::Warning, component.xpath + "/parentUID",
                          "parentUID '" + component.parentUid + "' names no geometric component; " +
                              (component.uid.empty() ? component.xpath : component.uid) +
                              (enclosing ? " is attached to " + enclosing->uid : " is placed on its own")});
    component.parentUid = enclosing != nullptr ? enclosing->uid : "";
  }
}

ComponentGraph ComponentGraph::build(const DOMElement& cpacsRoot, const std::vector<ComponentLocation>& locations,
                                     Problems& warnings) {
  ComponentGraph result;
  const std::vector<const DOMElement*> modelElements = models(cpacsRoot);
  for (std::size_t model = 0; model < modelElements.size(); ++model) {
    for (const auto& location : locations) {
      std::vector<const DOMElement*> found;
      select(*modelElements[model], split(location.pathInModel), 0, found);
      for (const DOMElement* element : found) result.add(*element, location, model);
    }
  }
  result.resolveParents(warnings);

  // Edges run from parent to child.
  const std::size_t count = result.components_.size();
  Graph graph(count);
  std::vector<bool> hasParent(count, false);
  for (std::size_t i = 0; i < count; ++i) {
    const long parent = result.find(result.components_[i].parentUid);
    if (parent < 0) continue;
    boost::add_edge(static_cast<std::size_t>(parent), i, graph);
    hasParent[i] = true;
  }

  std::vector<std::size_t> strongComponent(count);
  const std::size_t strongCount = count == 0 ? 0 : boost::strong_components(graph, strongComponent.data());
  std::map<std::size_t, std::vector<std::string>> members;
  for (std::size_t i = 0; i < count; ++i) members[strongComponent[i]].push_back(result.components_[i].uid);
  for (std::size_t i = 0; i < count; ++i) {
    const auto& cycle = members[strongComponent[i]];
    const bool selfLoop = result.components_[i].parentUid == result.components_[i].uid;
    if (cycle.size() > 1 || selfLoop) {
      std::string names;
      for (const auto& uid : cycle) names += (names.empty() ? "" : " -> ") + uid;
      throw Error(ErrorCode::InvalidModel,
                  "parentUID cycle between components " + names + (selfLoop ? " (its own parent)" : ""), {},
                  result.components_[i].xpath);
    }
  }
  (void)strongCount;

  std::vector<boost::default_color_type> colors(count, boost::white_color);
  DiscoveryRecorder recorder(result.order_);
  for (std::size_t i = 0; i < count; ++i)
    if (!hasParent[i]) boost::depth_first_visit(graph, i, recorder, colors.data());

  result.depth_.assign(count, 0);
  for (std::size_t index : result.order_) {
    for (auto [edge, end] = boost::out_edges(index, graph); edge != end; ++edge)
      result.depth_[boost::target(*edge, graph)] = result.depth_[index] + 1;
  }
  return result;
}

}  // namespace airshape::graph
