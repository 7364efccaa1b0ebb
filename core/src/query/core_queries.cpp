#include "airshape/query/core_queries.h"

#include "airshape/configuration.h"
#include "airshape/error.h"

namespace airshape::query {

void registerCoreQueries(QueryRegistry& registry) {
  registry.add({"bounding_box", "core", "[uid] -> {min, max}: tight box of a component or of the whole configuration",
                [](Configuration& configuration, const Json& query) -> Json {
                  const auto& graph = configuration.components();
                  if (query.contains("uid")) {
                    const std::string uid = query.at("uid").is_string() ? query.at("uid").get<std::string>() : "";
                    const long index = graph.find(uid);
                    if (index < 0)
                      throw Error(ErrorCode::InvalidArgument, "no geometric component with uID '" + uid + "'");
                    throw Error(ErrorCode::NotImplemented,
                                "no builder yet for " + graph.components()[static_cast<std::size_t>(index)].nodeType);
                  }
                  throw Error(ErrorCode::NotImplemented, "no builder yet for the configuration's components");
                }});
}

}  // namespace airshape::query
