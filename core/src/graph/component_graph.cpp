#include "airshape/graph/component_graph.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/depth_first_search.hpp>
#include <boost/graph/strong_components.hpp>
#include <xercesc/dom/DOM.hpp>

#include "airshape/error.h"
#include "airshape/schema/node_lookup.h"
#include "airshape/xml/text.h"

namespace airshape::graph {

using namespace xercesc;

namespace {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;

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

/// The locations of one declaration: its path below the model, or below every location of
/// the node type it lies in (`resolving` guards against declarations that contain each other).
void resolve(const ComponentLocation& declaration, const std::vector<ComponentLocation>& declared,
             std::set<std::string>& resolving, std::vector<ComponentLocation>& resolved) {
  ComponentLocation location = declaration;
  if (location.typeName.empty()) location.typeName = location.nodeType;
  location.within.clear();
  if (declaration.within.empty()) {
    resolved.push_back(location);
    return;
  }
  if (!resolving.insert(declaration.within).second) return;
  for (const ComponentLocation& container : declared) {
    if (container.nodeType != declaration.within) continue;
    std::vector<ComponentLocation> containers;
    resolve(container, declared, resolving, containers);
    for (const ComponentLocation& outer : containers) {
      ComponentLocation inner = location;
      inner.pathInModel =
          outer.pathInModel.empty() ? location.pathInModel : outer.pathInModel + "/" + location.pathInModel;
      inner.listed = location.listed && outer.listed;
      resolved.push_back(inner);
    }
  }
  resolving.erase(declaration.within);
}

/// Calls `found` for every element below `element` whose path from the model is one of the
/// locations', in document order; descends only where a location's path continues.
void collect(const DOMElement& element, const std::string& path, const std::map<std::string, std::size_t>& atPath,
             const std::set<std::string>& prefixes, const std::function<void(const DOMElement&, std::size_t)>& found) {
  for (const DOMElement* child = xml::firstElement(element); child != nullptr; child = xml::nextElement(*child)) {
    const std::string childPath = (path.empty() ? "" : path + "/") + xml::name(*child);
    if (prefixes.count(childPath) == 0) continue;
    const auto location = atPath.find(childPath);
    if (location != atPath.end()) found(*child, location->second);
    collect(*child, childPath, atPath, prefixes, found);
  }
}

/// A copy of a declaration with one trait changed: the steps of the declarations' sentences.
template <class Trait>
ComponentLocation with(ComponentLocation location, Trait ComponentLocation::*trait, Trait value) {
  location.*trait = std::move(value);
  return location;
}

}  // namespace

ComponentLocation ComponentLocation::inside(std::string container) const {
  return with(*this, &ComponentLocation::within, std::move(container));
}
ComponentLocation ComponentLocation::typed(std::string protocolType) const {
  return with(*this, &ComponentLocation::typeName, std::move(protocolType));
}
ComponentLocation ComponentLocation::asPart() const { return with(*this, &ComponentLocation::part, true); }
ComponentLocation ComponentLocation::asInsideParent() const {
  return with(*this, &ComponentLocation::insideParent, true);
}
ComponentLocation ComponentLocation::asStructure() const {
  return with(asInsideParent(), &ComponentLocation::structure, true);
}
ComponentLocation ComponentLocation::inBox() const { return with(*this, &ComponentLocation::inConfigurationBox, true); }
ComponentLocation ComponentLocation::unlisted() const { return with(*this, &ComponentLocation::listed, false); }
ComponentLocation ComponentLocation::asGroup() const { return with(*this, &ComponentLocation::group, true); }
ComponentLocation ComponentLocation::placedByItsTransformation() const {
  return with(*this, &ComponentLocation::placedByTransformation, true);
}
ComponentLocation ComponentLocation::leftOutWhen(
    std::function<std::optional<Problem>(const schema::Node&)> check) const {
  return with(*this, &ComponentLocation::unbuildable, std::move(check));
}

std::vector<ComponentLocation> resolveLocations(const std::vector<ComponentLocation>& declared) {
  std::vector<ComponentLocation> resolved = {ComponentLocation{kModelNodeType, "", "plane"}.asPart()};
  for (const ComponentLocation& declaration : declared) {
    std::set<std::string> resolving;
    resolve(declaration, declared, resolving, resolved);
  }
  return resolved;
}

long ComponentGraph::find(const std::string& uid) const {
  const auto entry = byUid_.find(uid);
  return entry == byUid_.end() || uid.empty() ? -1 : static_cast<long>(entry->second);
}

std::string ComponentGraph::leftOutReason(const Component& component) const {
  for (const Component* above = &component; above != nullptr;) {
    if (above->unbuildable) return above->unbuildable->message;
    const long parent = find(above->parentUid);
    above = parent < 0 ? nullptr : &components_[static_cast<std::size_t>(parent)];
  }
  return {};
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
  component.placedByTransformation = location.placedByTransformation;
  if (const DOMElement* parent = xml::firstChild(element, "parentUID")) component.parentUid = xml::text(*parent);
  component.parentUid.erase(0, component.parentUid.find_first_not_of(" \t\r\n"));
  component.parentUid.erase(component.parentUid.find_last_not_of(" \t\r\n") + 1);
  component.xpath = xml::pathOf(element);
  component.model = model;
  component.element = &element;
  components_.push_back(std::move(component));
}

void ComponentGraph::checkBuildable(const DOMElement& element, const ComponentLocation& location,
                                    schema::Node& typedModel, Problems& warnings) {
  if (components_.empty() || components_.back().element != &element) return;  // a repeated uID: not added
  const schema::Node* node = schema::nodeBoundTo(typedModel, element);
  if (node == nullptr) return;
  if (std::optional<Problem> why = location.unbuildable(*node)) {
    warnings.push_back(*why);
    components_.back().unbuildable = std::move(why);
  }
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
                                     schema::Node& typedModel, Problems& warnings) {
  ComponentGraph result;
  const std::vector<const DOMElement*> modelElements = models(cpacsRoot);
  std::map<std::string, std::size_t> atPath;  // the first location declared at a path claims it
  std::set<std::string> prefixes;
  for (std::size_t i = 0; i < locations.size(); ++i) {
    const std::string& path = locations[i].pathInModel;
    atPath.emplace(path, i);
    for (std::size_t slash = path.find('/'); slash != std::string::npos; slash = path.find('/', slash + 1))
      prefixes.insert(path.substr(0, slash));
    prefixes.insert(path);
  }
  for (std::size_t model = 0; model < modelElements.size(); ++model) {
    const auto modelLocation = atPath.find("");
    if (modelLocation != atPath.end()) result.add(*modelElements[model], locations[modelLocation->second], model);
    collect(*modelElements[model], "", atPath, prefixes, [&](const DOMElement& element, std::size_t location) {
      result.add(element, locations[location], model);
      if (locations[location].unbuildable) result.checkBuildable(element, locations[location], typedModel, warnings);
    });
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
