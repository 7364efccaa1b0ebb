#pragma once

#include <string>
#include <vector>

#include "airshape/model/typed_components.h"
#include "airshape/query/arguments.h"

namespace airshape::query {

/// The node a query's `argument` names, by 1-based index or uID, among `list` (the components
/// of `nodeTypes` of the first model, which queries address). A uID that is not there says why:
/// it cannot be built, it is in another model of the file, or there is none
/// (model::throwNotInModel).
template <class T>
T& selectInFirstModel(const Configuration& configuration, const std::vector<T*>& list,
                      const std::vector<std::string>& nodeTypes, const Json& query, const char* argument,
                      const std::string& kind) {
  const auto named = query.find(argument);
  if (named != query.end() && named->is_string())
    model::findByUid(configuration, model::kAddressedModel, list, nodeTypes, named->template get<std::string>(), kind);
  return *list[selectByIndexOrUid(query, argument, model::uidsOf(list), kind)];
}

}  // namespace airshape::query
