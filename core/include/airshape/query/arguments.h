#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "airshape/query/query_registry.h"

namespace airshape::query {

// Reading the arguments of a query. Each function throws Error(InvalidArgument) with a
// one-line message naming the argument when it is missing or out of range.

double numberArgument(const Json& query, const char* name);
/// A number in [0, 1], such as eta, xsi or zeta.
double fractionArgument(const Json& query, const char* name);
std::string stringArgument(const Json& query, const char* name);
bool booleanArgument(const Json& query, const char* name);
/// A point or vector argument: [x, y, z] of finite numbers.
std::array<double, 3> pointArgument(const Json& query, const char* name);

/// Selects one of `uids` by a 1-based index or by uID, as the query protocol addresses
/// components; `what` names the kind in messages. Returns the 0-based index.
std::size_t selectByIndexOrUid(const Json& query, const char* name, const std::vector<std::string>& uids,
                               const std::string& what);

}  // namespace airshape::query
