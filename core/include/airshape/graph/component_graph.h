#pragma once

#include <string>
#include <vector>

#include "airshape/problem.h"
#include "airshape/xml/path.h"

namespace airshape::graph {

/// Where components of one CPACS node type live, relative to a model element
/// (/cpacs/vehicles/aircraft/model or /cpacs/vehicles/rotorcraft/model).
struct ComponentLocation {
  std::string nodeType;     ///< e.g. "wing"
  std::string pathInModel;  ///< e.g. "wings/wing"
};

/// The geometric components CPACS 3.5 defines, in the order `info` lists them.
const std::vector<ComponentLocation>& standardComponentLocations();

/// One geometric component of a model.
struct Component {
  std::string uid;
  std::string nodeType;
  std::string parentUid;  ///< empty: attached to nothing
  std::string xpath;
  std::size_t model = 0;  ///< index of the model (aircraft models first, then rotorcraft models)
  const xercesc::DOMElement* element = nullptr;
};

/// Components connected by parentUID, in an order that builds every parent before its children.
class ComponentGraph {
 public:
  /// Collects the components of every model. A parentUID that names no component is reported
  /// in `warnings` and the component is built on its own; a cycle throws Error(InvalidModel)
  /// naming the uIDs in it.
  static ComponentGraph build(const xercesc::DOMElement& cpacsRoot, const std::vector<ComponentLocation>& locations,
                              Problems& warnings);

  const std::vector<Component>& components() const { return components_; }
  /// Indices into components(): parents before children, siblings in document order.
  const std::vector<std::size_t>& buildOrder() const { return order_; }
  /// How many parents lie above the component (0 for a root).
  std::size_t depth(std::size_t index) const { return depth_[index]; }
  /// Index of the component with this uID, or -1.
  long find(const std::string& uid) const;

 private:
  std::vector<Component> components_;
  std::vector<std::size_t> order_;
  std::vector<std::size_t> depth_;
};

}  // namespace airshape::graph
