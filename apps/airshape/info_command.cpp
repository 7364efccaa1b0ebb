#include <iostream>

#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

int runInfo(const Arguments& arguments, plugin::PluginHost& host) {
  const std::string path = singleFileArgument(arguments, "info");
  const Configuration configuration = openConfiguration(path, host);
  const graph::ComponentGraph& graph = configuration.components();
  std::cout << "file:         " << path << '\n'
            << "CPACS:        " << configuration.cpacsVersion() << '\n'
            << "uIDs:         " << configuration.uids().size() << '\n'
            << "components:   " << graph.components().size() << " (in build order)\n";
  for (std::size_t index : graph.buildOrder()) {
    const graph::Component& component = graph.components()[index];
    const std::string plugin = host.pluginFor(component.nodeType);
    std::cout << "  " << std::string(2 * graph.depth(index), ' ') << component.nodeType << ' ' << component.uid
              << "  parent: " << (component.parentUid.empty() ? "-" : component.parentUid)
              << "  plugin: " << (plugin.empty() ? "none" : plugin) << '\n';
  }
  return kSuccess;
}

}  // namespace airshape::cli
