#include "airshape/query/query_service.h"

#include <cmath>
#include <optional>
#include <string>

#include <Standard_Failure.hxx>

#include "airshape/error.h"

namespace airshape::query {

namespace {

/// Whether every number in a result is finite (JSON has no NaN or infinity; they would
/// be written as null).
bool allFinite(const Json& value) {
  if (value.is_number_float()) return std::isfinite(value.get<double>());
  if (value.is_structured())
    for (const auto& element : value)
      if (!allFinite(element)) return false;
  return true;
}

/// The query a line holds, or the error answer for a line that is no JSON, or whose numbers
/// no double holds (nlohmann reports 1e400 as out of range, not as a parse error).
std::optional<Json> parsedQuery(const std::string& line, Json& error) {
  try {
    return Json::parse(line);
  } catch (const Json::parse_error&) {
    error = {{"error", "the line is not valid JSON"}};
  } catch (const Json::out_of_range&) {
    error = {{"error", "the line holds a number too large for a double"}};
  }
  return std::nullopt;
}

}  // namespace

Json answer(Configuration& configuration, const QueryRegistry& registry, const std::string& line) {
  try {
    Json error;
    const std::optional<Json> parsed = parsedQuery(line, error);
    if (!parsed) return error;
    const Json& query = *parsed;
    if (!query.is_object()) return {{"error", "a query must be a JSON object"}};
    const auto op = query.find("op");
    if (op == query.end() || !op->is_string()) return {{"error", "the query has no \"op\" string"}};
    const Op* registered = registry.find(op->get<std::string>());
    if (registered == nullptr) return {{"error", "unknown op '" + op->get<std::string>() + "'"}};
    Json result = registered->handler(configuration, query);
    if (!allFinite(result))
      return {{"error", "the result is not a finite number: the geometry is too large or degenerate"}};
    return {{"ok", std::move(result)}};
  } catch (const Error& error) {
    return {{"error", error.what()}};  // with the CPACS path of the node, when known
  } catch (const std::exception& error) {
    return {{"error", std::string("internal error: ") + error.what()}};
  } catch (const Standard_Failure& failure) {  // OCCT's exceptions are not std::exceptions
    return {{"error", std::string("geometry kernel failure (") + failure.DynamicType()->Name() +
                          "): " + failure.GetMessageString()}};
  }
}

void serveQueries(Configuration& configuration, const QueryRegistry& registry, std::istream& in, std::ostream& out) {
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    out << answer(configuration, registry, line).dump(-1, ' ', false, Json::error_handler_t::replace) << '\n'
        << std::flush;
  }
}

}  // namespace airshape::query
