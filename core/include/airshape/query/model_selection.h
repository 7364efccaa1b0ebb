#pragma once

#include <string>
#include <vector>

#include "airshape/model/primary_model.h"
#include "airshape/query/arguments.h"

namespace airshape::query {

/// The node a query's `argument` names, by 1-based index or uID, among `list` (one of the
/// first model's lists of wings or fuselages, which queries address). A uID that is not there
/// says why: left out on loading, in another model of the file, or none (model::throwNotInModel).
template <class T>
T& selectInFirstModel(const Configuration& configuration, const std::vector<T*>& list, const Json& query,
                      const char* argument, const std::string& kind) {
  const model::ModelComponents& model = model::primaryModel(configuration);
  const auto named = query.find(argument);
  if (named != query.end() && named->is_string())
    model::findByUid(configuration, model, list, named->template get<std::string>(), kind);
  return *list[selectByIndexOrUid(query, argument, model::uidsOf(list), kind)];
}

}  // namespace airshape::query
