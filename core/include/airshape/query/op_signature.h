#pragma once

#include <string>
#include <vector>

#include "airshape/query/query_registry.h"

namespace airshape::query {

/// What an op takes and answers, as its one-line summary states it: "uid, point, normal -> area
/// of the component's section by the plane". The names before the arrow are its arguments, those written in
/// brackets (`["deflection": metres]`) optional; the text after it is its answer. Bindings are
/// generated from it (docs/python.md, "Every op as a method").
struct OpSignature {
  std::vector<std::string> arguments;
  std::vector<std::string> optional;
  std::string answer;
};

OpSignature signatureOf(const Op& op);

/// Every op with its owner, summary and signature, as JSON: what `airshape plugins --json`
/// prints and the bindings are generated from.
Json describeOps(const QueryRegistry& registry);

}  // namespace airshape::query
