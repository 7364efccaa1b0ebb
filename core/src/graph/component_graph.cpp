#include "airshape/graph/component_graph.h"

#include <algorithm>
#include <map>
#include <sstream>

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

}  // namespace

const std::vector<ComponentLocation>& standardComponentLocations() {
  static const std::vector<ComponentLocation> locations = {
      {"fuselage", "fuselages/fuselage"},
      {"wing", "wings/wing"},
      {"engine", "engines/engine"},
      {"enginePylon", "enginePylons/enginePylon"},
      {"rotor", "rotors/rotor"},
      {"duct", "ducts/duct"},
      {"genericGeometryComponent", "genericGeometryComponents/genericGeometryComponent"},
  };
  return locations;
}

long ComponentGraph::find(const std::string& uid) const {
  for (std::size_t i = 0; i < components_.size(); ++i)
    if (components_[i].uid == uid) return static_cast<long>(i);
  return -1;
}

ComponentGraph ComponentGraph::build(const DOMElement& cpacsRoot, const std::vector<ComponentLocation>& locations,
                                     Problems& warnings) {
  ComponentGraph result;
  const std::vector<const DOMElement*> modelElements = models(cpacsRoot);
  for (std::size_t model = 0; model < modelElements.size(); ++model) {
    for (const auto& location : locations) {
      std::vector<const DOMElement*> found;
      select(*modelElements[model], split(location.pathInModel), 0, found);
      for (const DOMElement* element : found) {
        Component component;
        component.uid = xml::attribute(*element, "uID");
        if (result.find(component.uid) >= 0) continue;  // a repeated uID: the first definition wins
        component.nodeType = location.nodeType;
        if (const DOMElement* parent = xml::firstChild(*element, "parentUID")) component.parentUid = xml::text(*parent);
        component.parentUid.erase(0, component.parentUid.find_first_not_of(" \t\r\n"));
        component.parentUid.erase(component.parentUid.find_last_not_of(" \t\r\n") + 1);
        component.xpath = xml::pathOf(*element);
        component.model = model;
        component.element = element;
        result.components_.push_back(std::move(component));
      }
    }
  }

  // Edges run from parent to child; the first component with a uID is the one a parentUID names.
  const std::size_t count = result.components_.size();
  Graph graph(count);
  std::vector<bool> hasParent(count, false);
  for (std::size_t i = 0; i < count; ++i) {
    const Component& component = result.components_[i];
    if (component.parentUid.empty()) continue;
    const long parent = result.find(component.parentUid);
    if (parent < 0) {
      warnings.push_back({Problem::Severity::Warning, component.xpath + "/parentUID",
                          "parentUID '" + component.parentUid + "' names no geometric component; " + component.uid +
                              " is placed on its own"});
      continue;
    }
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
