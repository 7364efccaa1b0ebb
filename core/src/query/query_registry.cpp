#include "airshape/query/query_registry.h"

#include "airshape/error.h"

namespace airshape::query {

void QueryRegistry::add(Op op) {
  const auto existing = ops_.find(op.name);
  if (existing != ops_.end()) {
    throw Error(ErrorCode::PluginFailed, "query op '" + op.name + "' of " + op.owner + " is already registered by " +
                                             existing->second.owner + "; " + op.owner + "'s op is ignored");
  }
  const std::string name = op.name;
  ops_.emplace(name, std::move(op));
}

const Op* QueryRegistry::find(const std::string& name) const {
  const auto entry = ops_.find(name);
  return entry == ops_.end() ? nullptr : &entry->second;
}

std::vector<const Op*> QueryRegistry::ops() const {
  std::vector<const Op*> list;
  for (const auto& [name, op] : ops_) list.push_back(&op);
  return list;
}

}  // namespace airshape::query
