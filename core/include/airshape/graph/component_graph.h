#pragma once

#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "airshape/problem.h"
#include "airshape/schema/node.h"
#include "airshape/xml/path.h"

namespace airshape::graph {

/// Where components of one node type live and what they are. Plugins declare these for the
/// node types they build (docs/plugins.md, "Declaring node types"); the core knows no kind by
/// name. A declaration either gives a path relative to a model element
/// (/cpacs/vehicles/aircraft/model or /cpacs/vehicles/rotorcraft/model), or a path relative to
/// every element of another node type (`inside`): the core composes the two.
struct ComponentLocation {
  std::string nodeType{};     ///< what plugins claim, e.g. "sensorPod"
  std::string pathInModel{};  ///< e.g. "sensorPods/sensorPod"; "" the model; relative to `within` if set
  std::string typeName{};     ///< the component type of the query protocol; empty: the node type
  /// A part of its parent's solid (segments of a lofted body) or the model itself: a component
  /// that queries measure, but that `build` and `export` do not build on their own.
  bool part = false;
  /// Lies inside its parent's solid (devices cut from it, structure within it): built and
  /// measured on its own, but exported only when named, and not part of the configuration's
  /// box (its parent covers it).
  bool insideParent = false;
  /// Structure of its parent: surfaces that `export --structure` joins with its parent's faces
  /// into one connected shell.
  bool structure = false;
  /// Counts in the configuration's box and length (QUERY-components §7): the flying and the
  /// external parts, not what lies in or on them.
  bool inConfigurationBox = false;
  /// Listed by `component_list` (a component the reference library registers, QUERY-components
  /// §1). A declaration inside an unlisted node type's elements is unlisted too.
  bool listed = true;
  /// A compound of components that are exported on their own: built, measured and listed like
  /// any component, but exported only when named, so that an export writes no solid twice.
  bool group = false;
  /// Placed by its own `transformation` and its parent's origin (model::componentTransform):
  /// the components a model holds directly, not what lies in them.
  bool placedByTransformation = false;
  /// The node type whose elements hold this one; empty: the model element.
  std::string within{};
  /// Why an element cannot be built at all (given its node in the typed model), or nothing:
  /// such a component is left out of its model's lists (graph::ComponentGraph::leftOutReason)
  /// and a warning names it when the file is opened.
  std::function<std::optional<Problem>(const schema::Node&)> unbuildable{};

  /// The same declaration with another trait; they read as a sentence in a plugin:
  /// `ComponentLocation{"probe", "probes/probe"}.inside("sensorPod").asInsideParent()`.
  ComponentLocation inside(std::string container) const;
  ComponentLocation typed(std::string protocolType) const;
  ComponentLocation asPart() const;
  ComponentLocation asInsideParent() const;
  /// Inside its parent and joined with it by `export --structure`.
  ComponentLocation asStructure() const;
  ComponentLocation inBox() const;
  ComponentLocation unlisted() const;
  ComponentLocation asGroup() const;
  ComponentLocation placedByItsTransformation() const;
  ComponentLocation leftOutWhen(std::function<std::optional<Problem>(const schema::Node&)> check) const;
};

/// The node type of the model element itself (type `plane`), which has no shape.
inline const char* const kModelNodeType = "model";

/// The locations of the given declarations relative to a model element, the model's own first:
/// each declaration inside another node type once for every location of that type (recursively;
/// one inside a type nobody declares has none), its type name defaulting to its node type.
std::vector<ComponentLocation> resolveLocations(const std::vector<ComponentLocation>& declared);

/// One geometric component of a model.
struct Component {
  std::string uid;  ///< empty for an element without one (the schema requires it; validate says so)
  std::string nodeType;
  std::string typeName;                 ///< ComponentLocation::typeName
  bool part = false;                    ///< ComponentLocation::part
  bool insideParent = false;            ///< ComponentLocation::insideParent
  bool structure = false;               ///< ComponentLocation::structure
  bool inConfigurationBox = false;      ///< ComponentLocation::inConfigurationBox
  bool listed = true;                   ///< ComponentLocation::listed
  bool group = false;                   ///< ComponentLocation::group
  bool placedByTransformation = false;  ///< ComponentLocation::placedByTransformation
  std::optional<Problem> unbuildable;   ///< why it cannot be built (ComponentLocation::unbuildable)
  std::string parentUid;                ///< its parentUID, else the component it lies in; empty: attached to nothing
  std::string xpath;
  std::size_t model = 0;  ///< index of the model (aircraft models first, then rotorcraft models)
  const xercesc::DOMElement* element = nullptr;
};

/// Components connected by parentUID, in an order that builds every parent before its children.
class ComponentGraph {
 public:
  /// Collects the components of every model, in document order, at the given locations
  /// (resolved: relative to a model element). A component inside another one is attached to
  /// it unless its parentUID names another component. A parentUID that
  /// names no component (nor an element the component lies in) is reported in `warnings` and
  /// the component is built on its own; a cycle throws Error(InvalidModel) naming the uIDs in it.
  /// `typedModel` (the document read into the generated model) is handed to the locations'
  /// `unbuildable` checks.
  static ComponentGraph build(const xercesc::DOMElement& cpacsRoot, const std::vector<ComponentLocation>& locations,
                              schema::Node& typedModel, Problems& warnings);

  const std::vector<Component>& components() const { return components_; }
  /// Indices into components(): parents before children, siblings in document order.
  const std::vector<std::size_t>& buildOrder() const { return order_; }
  /// How many parents lie above the component (0 for a root).
  std::size_t depth(std::size_t index) const { return depth_[index]; }
  /// Index of the component with this uID, or -1.
  long find(const std::string& uid) const;
  /// The component with this uID; throws Error(InvalidArgument) when no component has it.
  const Component& named(const std::string& uid) const;
  /// Why the component, or one it lies in, cannot be built ("" when nothing says so).
  std::string leftOutReason(const Component& component) const;

 private:
  /// Adds a component found at `location`, unless one before it in the document holds its uID.
  void add(const xercesc::DOMElement& element, const ComponentLocation& location, std::size_t model);
  /// Records why the component just added for `element` cannot be built, if its location's
  /// check says so.
  void checkBuildable(const xercesc::DOMElement& element, const ComponentLocation& location, schema::Node& typedModel,
                      Problems& warnings);
  /// Attaches each component to its parent: the one its parentUID names, else the one it lies in.
  void resolveParents(Problems& warnings);

  std::vector<Component> components_;
  std::unordered_map<std::string, std::size_t> byUid_;
  std::vector<std::size_t> order_;
  std::vector<std::size_t> depth_;
};

}  // namespace airshape::graph
