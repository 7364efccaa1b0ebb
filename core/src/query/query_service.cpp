#include "airshape/query/query_service.h"

#include <string>

#include <Standard_Failure.hxx>

#include "airshape/error.h"

namespace airshape::query {

Json answer(Configuration& configuration, const QueryRegistry& registry, const std::string& line) {
  try {
    const Json query = Json::parse(line);
    if (!query.is_object()) return {{"error", "a query must be a JSON object"}};
    const auto op = query.find("op");
    if (op == query.end() || !op->is_string()) return {{"error", "the query has no \"op\" string"}};
    const Op* registered = registry.find(op->get<std::string>());
    if (registered == nullptr) return {{"error", "unknown op '" + op->get<std::string>() + "'"}};
    return {{"ok", registered->handler(configuration, query)}};
  } catch (const Json::parse_error&) {
    return {{"error", "the line is not valid JSON"}};
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
