#include "airshape/plugin/plugin_host.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <boost/dll/import.hpp>
#include <boost/dll/runtime_symbol_info.hpp>
#include <boost/dll/shared_library.hpp>

#include "airshape/error.h"
#include "airshape/query/core_queries.h"

namespace airshape::plugin {

namespace fs = std::filesystem;

namespace {

constexpr const char* kBuiltInPrefix = "libairshape_plugin_";

bool isSharedLibrary(const fs::path& path) { return path.extension() == ".so"; }

std::vector<fs::path> sortedEntries(const fs::path& folder) {
  std::vector<fs::path> entries;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) entries.push_back(entry.path());
  std::sort(entries.begin(), entries.end());
  return entries;
}

}  // namespace

PluginHost::PluginHost() { registerCoreQueries(queries_); }

std::string PluginHost::coreLibraryFolder() { return boost::dll::this_line_location().parent_path().string(); }

void PluginHost::loadDefaultPlugins() {
  loadFolder(coreLibraryFolder(), false);
  const char* extra = std::getenv("AIRSHAPE_PLUGIN_PATH");
  if (extra == nullptr) return;
  std::stringstream list(extra);
  for (std::string item; std::getline(list, item, ':');) {
    if (item.empty()) continue;
    std::error_code error;
    if (fs::is_directory(item, error)) {
      loadFolder(item, true);
    } else if (fs::exists(item, error)) {
      loadFile(item);
    } else {
      messages_.push_back("AIRSHAPE_PLUGIN_PATH: " + item + ": no such file or folder");
    }
  }
}

void PluginHost::loadFolder(const std::string& folder, bool anyName) {
  for (const fs::path& path : sortedEntries(folder)) {
    const std::string fileName = path.filename().string();
    if (!isSharedLibrary(path)) continue;
    if (!anyName && fileName.rfind(kBuiltInPrefix, 0) != 0) continue;
    loadFile(path.string());
  }
}

bool PluginHost::loadFile(const std::string& file) {
  const std::string canonical = fs::weakly_canonical(file).string();
  for (const auto& loaded : plugins_)
    if (loaded.file == canonical) return true;  // the same file found twice
  std::shared_ptr<Plugin> plugin;
  try {
    boost::dll::shared_library library(canonical, boost::dll::load_mode::rtld_lazy | boost::dll::load_mode::rtld_local);
    if (!library.has("airshape_plugin_abi_version") || !library.has("airshape_create_plugin")) {
      messages_.push_back(canonical + ": not an airshape plugin (no airshape_create_plugin factory); skipped");
      return false;
    }
    const int abi = library.get_alias<int()>("airshape_plugin_abi_version")();
    if (abi != AIRSHAPE_PLUGIN_ABI_VERSION) {
      messages_.push_back(canonical + ": built for plugin ABI version " + std::to_string(abi) + ", this core has " +
                          std::to_string(AIRSHAPE_PLUGIN_ABI_VERSION) +
                          "; rebuild the plugin against this core; skipped");
      return false;
    }
    // import_alias keeps the library loaded for as long as the returned function exists;
    // the plugin object's deleter holds that function, and with it the library.
    auto factory = boost::dll::import_alias<std::shared_ptr<Plugin>()>(library, "airshape_create_plugin");
    std::shared_ptr<Plugin> created = factory();
    plugin = std::shared_ptr<Plugin>(created.get(), [created, factory](Plugin*) mutable { created.reset(); });
  } catch (const std::exception& error) {
    messages_.push_back(canonical + ": cannot be loaded as a plugin (" + std::string(error.what()) + "); skipped");
    return false;
  }

  LoadedPlugin loaded{canonical, plugin, {}};
  for (const NodeType& type : plugin->nodeTypes()) {
    const std::string owner = pluginFor(type.name);
    if (!owner.empty()) {
      messages_.push_back(canonical + ": plugin " + plugin->name() + " claims node type '" + type.name +
                          "', which plugin " + owner + " builds already; the claim is ignored");
      continue;
    }
    loaded.nodeTypes.push_back(type);
  }
  query::QueryRegistry ops;
  plugin->registerQueries(ops);
  for (const query::Op* op : ops.ops()) {
    query::Op copy = *op;
    copy.owner = plugin->name();
    try {
      queries_.add(std::move(copy));
    } catch (const Error& error) {
      messages_.push_back(canonical + ": " + error.message());
    }
  }
  ComponentShapes offered;
  plugin->registerShapeBuilders(offered);
  for (const NodeType& type : loaded.nodeTypes)  // only for the node types it was granted
    if (const ShapeBuilder* builder = offered.find(type.name)) shapes_.add(type.name, *builder);
  plugins_.push_back(std::move(loaded));
  return true;
}

std::vector<graph::ComponentLocation> PluginHost::componentLocations() const {
  std::vector<graph::ComponentLocation> locations = graph::standardComponentLocations();
  for (const auto& loaded : plugins_) {
    for (const NodeType& type : loaded.nodeTypes) {
      const bool known = std::any_of(locations.begin(), locations.end(),
                                     [&](const graph::ComponentLocation& l) { return l.nodeType == type.name; });
      if (!known && !type.pathInModel.empty()) locations.push_back({type.name, type.pathInModel, type.name});
    }
  }
  return locations;
}

std::string PluginHost::pluginFor(const std::string& nodeType) const {
  for (const auto& loaded : plugins_)
    for (const NodeType& type : loaded.nodeTypes)
      if (type.name == nodeType) return loaded.plugin->name();
  return {};
}

PluginHost& processPlugins() {
  static PluginHost loaded = [] {
    PluginHost host;
    host.loadDefaultPlugins();
    return host;
  }();
  return loaded;
}

}  // namespace airshape::plugin
