#pragma once
// What the plugin benchmarks share: the shared data folder and one loaded plugin host.
#include <string>

#include "airshape/configuration.h"
#include "airshape/plugin/plugin_host.h"

namespace airshape::bench {

inline std::string sharedCpacs(const std::string& name) {
  return std::string(AIRSHAPE_SHARED_DATA) + "/data/cpacs/" + name;
}

inline plugin::PluginHost& host() { return plugin::processPlugins(); }

/// Opens a file as the airshape command does: the plugins' component types and solids.
inline Configuration openWithPlugins(const std::string& path) {
  Configuration configuration = Configuration::open(path, host().componentLocations());
  configuration.useShapes(host().shapes());
  return configuration;
}

}  // namespace airshape::bench
