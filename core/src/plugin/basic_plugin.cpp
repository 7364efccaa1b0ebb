#include "airshape/plugin/basic_plugin.h"

#include "airshape/error.h"

namespace airshape::plugin {

void registerPendingOps(query::QueryRegistry& registry, const std::string& nodeType,
                        const std::vector<PendingOp>& ops) {
  for (const PendingOp& op : ops) {
    const std::string name = op.name;
    registry.add({name, "", std::string(op.summary) + " (no builder yet)",
                  [nodeType, name](Configuration&, const query::Json&) -> query::Json {
                    throw Error(ErrorCode::NotImplemented,
                                "no builder yet for " + nodeType + ": op '" + name + "' needs its geometry");
                  }});
  }
}

}  // namespace airshape::plugin
