#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "airshape/error.h"
#include "airshape/plugin/plugin_host.h"
#include "airshape/query/op_signature.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

namespace {

/// The node types a plugin builds, each once, in the order it declares them (a node type may be
/// declared at several places).
std::vector<std::string> nodeTypeNames(const plugin::LoadedPlugin& loaded) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto& type : loaded.nodeTypes)
    if (seen.insert(type.nodeType).second) names.push_back(type.nodeType);
  return names;
}

/// The plugins and every op with its signature, as JSON (what the bindings are generated from).
int printJson(plugin::PluginHost& host) {
  query::Json plugins = query::Json::array();
  for (const auto& loaded : host.plugins()) {
    plugins.push_back({{"name", loaded.plugin->name()},
                       {"version", loaded.plugin->version()},
                       {"file", loaded.file},
                       {"node_types", nodeTypeNames(loaded)}});
  }
  std::cout << query::Json{{"plugin_abi", AIRSHAPE_PLUGIN_ABI_VERSION},
                           {"plugins", plugins},
                           {"ops", query::describeOps(host.queries())}}
                   .dump(2)
            << '\n';
  return kSuccess;
}

}  // namespace

int runPlugins(const Arguments& arguments, plugin::PluginHost& host) {
  if (arguments.size() == 1 && arguments[0] == "--json") return printJson(host);
  if (!arguments.empty()) throw Error(ErrorCode::InvalidArgument, "usage: airshape plugins [--json]");
  std::cout << "plugin ABI version " << AIRSHAPE_PLUGIN_ABI_VERSION << "; core plugins from "
            << plugin::PluginHost::coreLibraryFolder() << '\n';
  for (const auto& loaded : host.plugins()) {
    std::cout << '\n'
              << loaded.plugin->name() << ' ' << loaded.plugin->version() << " - " << loaded.plugin->description()
              << "\n  file:       " << loaded.file;
    for (const plugin::Requirement& requirement : loaded.plugin->requirements())
      std::cout << "\n  requires:   " << requirement.plugin << plugin::describeRange(requirement);
    std::cout << "\n  node types:";
    for (const std::string& name : nodeTypeNames(loaded)) std::cout << ' ' << name;
    std::cout << "\n  query ops: ";
    for (const query::Op* op : host.queries().ops())
      if (op->owner == loaded.plugin->name()) std::cout << ' ' << op->name;
    std::cout << '\n';
  }
  if (const std::string flags = optionFlagsHelp(host); !flags.empty())
    std::cout << "\nbuild options (flags of build, export, view and query; off unless given):\n" << flags;
  std::cout << "\ncore query ops:";
  for (const query::Op* op : host.queries().ops())
    if (op->owner == "core") std::cout << ' ' << op->name;
  std::cout << '\n';
  return kSuccess;
}

}  // namespace airshape::cli
