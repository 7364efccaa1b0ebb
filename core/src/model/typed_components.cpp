#include "airshape/model/typed_components.h"

#include <algorithm>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "airshape/schema/node_lookup.h"

namespace airshape::model {

std::size_t modelHolding(const Configuration& configuration, const std::string& uid) {
  const long index = configuration.components().find(uid);
  if (index < 0) throw Error(ErrorCode::InvalidArgument, "no geometric component with uID '" + uid + "'");
  return configuration.components().components()[static_cast<std::size_t>(index)].model;
}

std::size_t modelCount(const Configuration& configuration) {
  std::size_t count = 0;
  for (const graph::Component& component : configuration.components().components())
    count = std::max(count, component.model + 1);
  return count;
}

std::vector<schema::Node*> componentNodes(const Configuration& configuration, std::size_t model,
                                          const std::vector<std::string>& nodeTypes) {
  const graph::ComponentGraph& graph = configuration.components();
  std::vector<schema::Node*> nodes;
  for (const std::string& nodeType : nodeTypes)
    for (const graph::Component& component : graph.components()) {
      if (component.model != model || component.nodeType != nodeType || component.unbuildable) continue;
      if (schema::Node* node = schema::nodeBoundTo(configuration.cpacs(), *component.element)) nodes.push_back(node);
    }
  return nodes;
}

void throwNotInModel(const Configuration& configuration, std::size_t model, const std::vector<std::string>& nodeTypes,
                     const std::string& uid, const std::string& kind) {
  const graph::ComponentGraph& graph = configuration.components();
  const long index = graph.find(uid);
  if (index >= 0) {
    const graph::Component& component = graph.components()[static_cast<std::size_t>(index)];
    const bool ofTheseTypes = std::find(nodeTypes.begin(), nodeTypes.end(), component.nodeType) != nodeTypes.end();
    if (ofTheseTypes && component.unbuildable)  // cannot be built: say why
      throw Error(ErrorCode::InvalidModel, component.unbuildable->message, {}, component.unbuildable->xpath);
    if (ofTheseTypes && component.model != model && model == kAddressedModel)
      throw Error(ErrorCode::InvalidArgument,
                  "no " + kind + " with uID '" + uid + "' in the first model, which queries address ('" + uid +
                      "' is in model " + std::to_string(component.model + 1) + " of the file)");
  }
  throw Error(ErrorCode::InvalidArgument, "no " + kind + " with uID '" + uid + "' in the model");
}

}  // namespace airshape::model
