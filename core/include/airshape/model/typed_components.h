#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "airshape/schema/node.h"

namespace airshape {
class Configuration;
}

namespace airshape::model {

/// The index of the model that queries address: the first aircraft model, else the first
/// rotorcraft model (as the established CPACS tools choose it); models count aircraft models
/// first, then rotorcraft models (graph::Component::model).
constexpr std::size_t kAddressedModel = 0;

/// The index of the model that holds the component with this uID (builders find a component in
/// its own model; `info`, `build` and `export` cover every model). Throws Error when no
/// component has the uID.
std::size_t modelHolding(const Configuration& configuration, const std::string& uid);

/// How many models the document holds.
std::size_t modelCount(const Configuration& configuration);

/// The typed nodes of the components of `model` whose node type is one of `nodeTypes` (those
/// types in turn, each in document order), without those that cannot be built
/// (graph::Component::unbuildable): so indices count only buildable components.
std::vector<schema::Node*> componentNodes(const Configuration& configuration, std::size_t model,
                                          const std::vector<std::string>& nodeTypes);

/// The same, as the generated type the plugin knows them by.
template <class T>
std::vector<T*> typedComponents(const Configuration& configuration, std::size_t model,
                                const std::vector<std::string>& nodeTypes) {
  std::vector<T*> typed;
  for (schema::Node* node : componentNodes(configuration, model, nodeTypes))
    if (T* component = dynamic_cast<T*>(node)) typed.push_back(component);
  return typed;
}

/// Throws the Error for a uID that names none of `model`'s components of `nodeTypes`: why it
/// cannot be built, if it cannot; that queries address the first model only, if another model
/// holds it; else that there is none (`kind` names what was sought).
[[noreturn]] void throwNotInModel(const Configuration& configuration, std::size_t model,
                                  const std::vector<std::string>& nodeTypes, const std::string& uid,
                                  const std::string& kind);

/// The node of `list` (components of `model` of `nodeTypes`) with this uID; see throwNotInModel.
template <class T>
T& findByUid(const Configuration& configuration, std::size_t model, const std::vector<T*>& list,
             const std::vector<std::string>& nodeTypes, const std::string& uid, const std::string& kind) {
  for (T* node : list)
    if (node->uID == uid) return *node;
  throwNotInModel(configuration, model, nodeTypes, uid, kind);
}

/// The buildable component of `nodeTypes` with this uID, in whichever model holds it; Error saying
/// why not (throwNotInModel).
template <class T>
T& typedComponentNamed(const Configuration& configuration, const std::vector<std::string>& nodeTypes,
                       const std::string& uid, const std::string& kind) {
  const std::size_t model = modelHolding(configuration, uid);
  return findByUid(configuration, model, typedComponents<T>(configuration, model, nodeTypes), nodeTypes, uid, kind);
}

/// The uIDs of a list of nodes, for selection by index or uID.
template <class T>
std::vector<std::string> uidsOf(const std::vector<T*>& nodes) {
  std::vector<std::string> uids;
  for (const T* node : nodes) uids.push_back(node->uID);
  return uids;
}

}  // namespace airshape::model
