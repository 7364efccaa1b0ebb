#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "airshape/problem.h"
#include "airshape/xml/path.h"

namespace airshape::graph {

/// Where components of one node type live, relative to a model element
/// (/cpacs/vehicles/aircraft/model or /cpacs/vehicles/rotorcraft/model).
struct ComponentLocation {
  std::string nodeType;     ///< what plugins claim, e.g. "wing" or "sparSegment"
  std::string pathInModel;  ///< e.g. "wings/wing"; a node type may live at several paths; "" the model
  std::string typeName;     ///< the component type of the query protocol, e.g. "wing_spar"
  /// A part of its parent's solid (a wing's segments and component segments, a fuselage's
  /// segments) or the model itself: a component that queries measure, but that `build` and
  /// `export` do not build on their own.
  bool part = false;
  /// Lies inside its parent's solid (control devices cut from it, structure within it):
  /// built and measured on its own, but exported only when named, and not part of the
  /// configuration's box (its parent covers it).
  bool insideParent = false;
  /// Structure of its parent (spars, ribs, cells, frames, ...): surfaces that `export
  /// --structure` joins with its parent's faces into one connected shell.
  bool structure = false;
  /// Counts in the configuration's box and length (QUERY-components §7): the flying and the
  /// external parts, not what lies in or on them (nacelles, ducts, tanks, decks, systems).
  bool inConfigurationBox = false;
  /// Listed by `component_list`: a component the reference library registers (QUERY-components
  /// §1). Spoilers, wing fuel tanks, frames, stringers and a few more are built and measured
  /// like any component, but the reference has no component for them.
  bool listed = true;
  /// A compound of components that are exported on their own (a system's and a deck's
  /// components, a duct assembly's ducts): built, measured and listed like any component, but
  /// exported only when named, so that an export writes no solid twice.
  bool group = false;
};

/// The node type of the model element itself (type `plane`), which has no shape.
inline const char* const kModelNodeType = "model";

/// Every geometric element CPACS 3.5 defines, in the order `info` lists them: the components
/// of a model (wings, fuselages, engines, ...) and the elements inside them that are geometry
/// of their own (control devices, spars, ribs, cells, frames, decks, tanks, ...), and as parts
/// the model itself, the segments and component segments.
const std::vector<ComponentLocation>& standardComponentLocations();

/// One geometric component of a model.
struct Component {
  std::string uid;  ///< empty for an element without one (the schema requires it; validate says so)
  std::string nodeType;
  std::string typeName;             ///< ComponentLocation::typeName
  bool part = false;                ///< ComponentLocation::part
  bool insideParent = false;        ///< ComponentLocation::insideParent
  bool structure = false;           ///< ComponentLocation::structure
  bool inConfigurationBox = false;  ///< ComponentLocation::inConfigurationBox
  bool listed = true;               ///< ComponentLocation::listed
  bool group = false;               ///< ComponentLocation::group
  std::string parentUid;            ///< its parentUID, else the component it lies in; empty: attached to nothing
  std::string xpath;
  std::size_t model = 0;  ///< index of the model (aircraft models first, then rotorcraft models)
  const xercesc::DOMElement* element = nullptr;
};

/// Components connected by parentUID, in an order that builds every parent before its children.
class ComponentGraph {
 public:
  /// Collects the components of every model. A component inside another one (a spar in a
  /// wing) is attached to it unless its parentUID names another component. A parentUID that
  /// names no component (nor an element the component lies in) is reported in `warnings` and
  /// the component is built on its own; a cycle throws Error(InvalidModel) naming the uIDs in it.
  static ComponentGraph build(const xercesc::DOMElement& cpacsRoot, const std::vector<ComponentLocation>& locations,
                              Problems& warnings);

  const std::vector<Component>& components() const { return components_; }
  /// Indices into components(): parents before children, siblings in document order.
  const std::vector<std::size_t>& buildOrder() const { return order_; }
  /// How many parents lie above the component (0 for a root).
  std::size_t depth(std::size_t index) const { return depth_[index]; }
  /// Index of the component with this uID, or -1.
  long find(const std::string& uid) const;
  /// The component with this uID; throws Error(InvalidArgument) when no component has it.
  const Component& named(const std::string& uid) const;

 private:
  /// Adds a component found at `location`, unless an earlier one holds its uID.
  void add(const xercesc::DOMElement& element, const ComponentLocation& location, std::size_t model);
  /// Attaches each component to its parent: the one its parentUID names, else the one it lies in.
  void resolveParents(Problems& warnings);

  std::vector<Component> components_;
  std::unordered_map<std::string, std::size_t> byUid_;
  std::vector<std::size_t> order_;
  std::vector<std::size_t> depth_;
};

}  // namespace airshape::graph
