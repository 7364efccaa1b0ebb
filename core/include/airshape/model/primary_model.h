#pragma once

#include <string>
#include <vector>

#include "airshape/problem.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}
namespace airshape::graph {
struct Component;
}

namespace airshape::model {

/// The wings and fuselages of one model (an aircraft or rotorcraft `model` element). In a
/// rotorcraft model the rotor blades follow the wings.
///
/// A wing or fuselage whose segments do not form one continuous chain cannot be built; it
/// is left out (so indices count only buildable components) and `skipped` says why.
struct ModelComponents {
  std::vector<schema::WingType*> wings;
  std::vector<schema::FuselageType*> fuselages;
  Problems skipped;
  std::vector<std::string> skippedUids;  ///< the uIDs of the components left out
};

/// Every model of a document: the aircraft models, then the rotorcraft models, in document
/// order (the order of graph::Component::model).
std::vector<ModelComponents> everyModel(const schema::CpacsType& cpacs);
/// The same for an open configuration, worked out once and kept in its cache.
const std::vector<ModelComponents>& everyModel(const Configuration& configuration);

/// The model queries address: the first aircraft model, else the first rotorcraft model (as
/// the established CPACS tools choose it). Empty when the document has neither.
const ModelComponents& primaryModel(const Configuration& configuration);
ModelComponents primaryModel(const schema::CpacsType& cpacs);

/// The model that holds the geometric component with this uID (builders find a component in
/// its own model; `info`, `build` and `export` cover every model). Throws Error when no
/// component has the uID.
const ModelComponents& modelHolding(const Configuration& configuration, const std::string& uid);

/// Whether the component, or one it lies in, was left out on loading (a wing or fuselage
/// whose segments form no chain).
bool leftOut(const Configuration& configuration, const graph::Component& component);

/// Throws the Error for a uID that names no wing or fuselage of `model`: why it was left out
/// on loading, if it was; that queries address the first model only, if another model holds
/// it; else that there is none (`kind` names what was sought).
[[noreturn]] void throwNotInModel(const Configuration& configuration, const ModelComponents& model,
                                  const std::string& uid, const std::string& kind);

/// The node of `list` (one of `model`'s wings or fuselages) with this uID; see throwNotInModel.
template <class T>
const T& findByUid(const Configuration& configuration, const ModelComponents& model, const std::vector<T*>& list,
                   const std::string& uid, const std::string& kind) {
  for (const T* node : list)
    if (node->uID == uid) return *node;
  throwNotInModel(configuration, model, uid, kind);
}

/// The uIDs of a list of nodes, for selection by index or uID.
template <class T>
std::vector<std::string> uidsOf(const std::vector<T*>& nodes) {
  std::vector<std::string> uids;
  for (const T* node : nodes) uids.push_back(node->uID);
  return uids;
}

}  // namespace airshape::model
