#include <iostream>
#include <set>

#include "airshape/error.h"
#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

int runPlugins(const Arguments& arguments, plugin::PluginHost& host) {
  if (!arguments.empty()) throw Error(ErrorCode::InvalidArgument, "usage: airshape plugins");
  std::cout << "plugin ABI version " << AIRSHAPE_PLUGIN_ABI_VERSION << "; core plugins from "
            << plugin::PluginHost::coreLibraryFolder() << '\n';
  for (const auto& loaded : host.plugins()) {
    std::cout << '\n'
              << loaded.plugin->name() << ' ' << loaded.plugin->version() << " - " << loaded.plugin->description()
              << "\n  file:       " << loaded.file;
    for (const plugin::Requirement& requirement : loaded.plugin->requirements())
      std::cout << "\n  requires:   " << requirement.plugin << plugin::describeRange(requirement);
    std::cout << "\n  node types:";
    std::set<std::string> shown;  // a node type may be declared at several places
    for (const auto& type : loaded.nodeTypes)
      if (shown.insert(type.nodeType).second) std::cout << ' ' << type.nodeType;
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
