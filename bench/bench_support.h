#pragma once
// What the plugin benchmarks share: the shared data folder and one loaded plugin host.
#include <string>

#include "airshape/plugin/plugin_host.h"

namespace airshape::bench {

inline std::string sharedCpacs(const std::string& name) {
  return std::string(AIRSHAPE_SHARED_DATA) + "/data/cpacs/" + name;
}

inline plugin::PluginHost& host() {
  static plugin::PluginHost loaded = [] {
    plugin::PluginHost h;
    h.loadDefaultPlugins();
    return h;
  }();
  return loaded;
}

}  // namespace airshape::bench
