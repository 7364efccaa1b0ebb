#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace airshape {
class Configuration;
}

namespace airshape::query {

using Json = nlohmann::json;

/// Answers one query: takes the configuration and the query object (with "op" and the
/// op's arguments) and returns the result. Throws Error for a bad query.
using Handler = std::function<Json(Configuration& configuration, const Json& query)>;

/// One query op, as listed by `airshape plugins`.
struct Op {
  std::string name;
  std::string owner;    ///< the plugin (or "core") that registered it
  std::string summary;  ///< one line: arguments and result
  Handler handler;
};

/// The ops `airshape query` answers. Plugins add theirs when they are loaded.
class QueryRegistry {
 public:
  /// Adds an op. Throws Error(PluginFailed) if another owner registered that name already.
  void add(Op op);
  const Op* find(const std::string& name) const;
  std::vector<const Op*> ops() const;

 private:
  std::map<std::string, Op> ops_;
};

}  // namespace airshape::query
