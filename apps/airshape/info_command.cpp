#include <iostream>

#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

namespace {

/// Who builds a component: its plugin, that plugin with "(no builder yet)" or "(not built: why)",
/// "none loaded", or for the model, nobody (it has no shape).
std::string builderOf(const graph::Component& component, const plugin::PluginHost& host) {
  if (component.nodeType == graph::kModelNodeType) return "- (the model: no shape)";
  const std::string plugin = host.pluginFor(component.nodeType);
  if (plugin.empty()) return "none loaded";
  if (host.shapes().find(component.nodeType) != nullptr) return plugin;
  if (const std::string* why = host.shapes().declined(component.nodeType)) return plugin + " (not built: " + *why + ")";
  return plugin + " (no builder yet)";
}

}  // namespace

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
    std::cout << "  " << std::string(2 * graph.depth(index), ' ') << component.typeName << ' '
              << (component.uid.empty() ? component.xpath : component.uid)
              << "  parent: " << (component.parentUid.empty() ? "-" : component.parentUid)
              << (component.model > 0 ? "  model: " + std::to_string(component.model + 1) : "")
              << "  plugin: " << builderOf(component, host) << '\n';
  }
  return kSuccess;
}

}  // namespace airshape::cli
