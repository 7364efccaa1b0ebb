#pragma once

#include <istream>
#include <ostream>

#include "airshape/query/query_registry.h"

namespace airshape::query {

/// Answers one query line: {"ok": result} or {"error": message}; never throws.
Json answer(Configuration& configuration, const QueryRegistry& registry, const std::string& line);

/// The `airshape query` loop: one JSON object per input line, one answer line each, in
/// order, flushed at once so that a caller can talk to the process interactively.
void serveQueries(Configuration& configuration, const QueryRegistry& registry, std::istream& in, std::ostream& out);

}  // namespace airshape::query
