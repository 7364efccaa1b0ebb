#pragma once

#include <string>
#include <vector>

#include "airshape/problem.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::model {

/// The wings and fuselages of the model that queries address: the first aircraft model,
/// else the first rotorcraft model (as the established CPACS tools choose it). Empty when
/// the document has neither. In a rotorcraft model the rotor blades follow the wings.
///
/// A wing or fuselage whose segments do not form one continuous chain cannot be built; it
/// is left out (so indices count only buildable components) and `skipped` says why.
struct PrimaryModel {
  std::vector<schema::WingType*> wings;
  std::vector<schema::FuselageType*> fuselages;
  Problems skipped;
};

PrimaryModel primaryModel(const schema::CpacsType& cpacs);

/// The same for an open configuration, worked out once and kept in its cache.
const PrimaryModel& primaryModel(const Configuration& configuration);

/// Throws the Error for a uID that names no wing or fuselage of the model: why it was left
/// out on loading, if it was, else that there is none (`kind` names what was sought).
[[noreturn]] void throwNotInModel(const Configuration& configuration, const std::string& uid, const std::string& kind);

/// The node of `list` (the model's wings or fuselages) with this uID; see throwNotInModel.
template <class T>
const T& findByUid(const Configuration& configuration, const std::vector<T*>& list, const std::string& uid,
                   const std::string& kind) {
  for (const T* node : list)
    if (node->uID == uid) return *node;
  throwNotInModel(configuration, uid, kind);
}

/// The uIDs of a list of nodes, for selection by index or uID.
template <class T>
std::vector<std::string> uidsOf(const std::vector<T*>& nodes) {
  std::vector<std::string> uids;
  for (const T* node : nodes) uids.push_back(node->uID);
  return uids;
}

}  // namespace airshape::model
