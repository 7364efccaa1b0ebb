#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "airshape/graph/component_graph.h"
#include "airshape/plugin/plugin.h"
#include "airshape/query/query_registry.h"

namespace airshape::plugin {

/// A plugin the host loaded, with the file it came from.
struct LoadedPlugin {
  std::string file;
  std::shared_ptr<Plugin> plugin;   ///< keeps its shared library loaded
  std::vector<NodeType> nodeTypes;  ///< those it was granted (a type claimed earlier stays with its first owner)
};

/// Finds, loads and registers plugins, those a plugin requires before it (they may be found
/// in any order). A plugin that cannot be used (not a shared library, no factory, another ABI
/// version, a required plugin missing or of another version, a node type or op that another
/// plugin has) yields one message in messages() and the rest keeps working.
class PluginHost {
 public:
  /// Registers the ops the core itself provides.
  PluginHost();
  /// Unloads the plugins in the reverse order of their registration: a plugin may hold what
  /// a plugin it requires offered it, whose code must outlive it.
  ~PluginHost();
  PluginHost(const PluginHost&) = default;
  PluginHost& operator=(const PluginHost&) = default;

  /// Loads the plugins next to the core library and those on AIRSHAPE_PLUGIN_PATH (a
  /// colon-separated list of folders or files), then registers them in dependency order.
  void loadDefaultPlugins();
  /// Loads every plugin in a folder (files libairshape_plugin_*.so, or any .so with `anyName`).
  void loadFolder(const std::string& folder, bool anyName);
  /// Loads one plugin file; on failure adds a message and returns false.
  bool loadFile(const std::string& file);

  const std::vector<LoadedPlugin>& plugins() const { return plugins_; }
  const std::vector<std::string>& messages() const { return messages_; }
  const query::QueryRegistry& queries() const { return queries_; }
  const ComponentShapes& shapes() const { return shapes_; }

  /// Where components live: the standard CPACS locations plus those plugins add.
  std::vector<graph::ComponentLocation> componentLocations() const;
  /// The name of the plugin that builds a node type, or "" if none does.
  std::string pluginFor(const std::string& nodeType) const;

  /// The folder holding the core library (where the built-in plugins are installed).
  static std::string coreLibraryFolder();

 private:
  /// Opens a plugin file and keeps the plugin pending; on failure adds a message.
  bool open(const std::string& file);
  void openFolder(const std::string& folder, bool anyName);
  void openPluginPath(const std::string& path);
  /// Why a plugin cannot be registered yet: a requirement no registered plugin meets.
  std::optional<std::string> unmetRequirement(const Plugin& plugin) const;
  /// Registers the pending plugins whose requirements are met, in dependency order; refuses
  /// the rest with one message each.
  void registerReadyPlugins();
  void registerPlugin(LoadedPlugin loaded);

  std::vector<LoadedPlugin> plugins_;
  std::vector<LoadedPlugin> pending_;  ///< opened, waiting for their requirements
  ServiceRegistry services_;
  std::vector<std::string> messages_;
  query::QueryRegistry queries_;
  ComponentShapes shapes_;
};

/// A requirement's version range for messages: " (version >= 0.1.0, < 1.0.0)", "" for any.
std::string describeRange(const Requirement& requirement);

/// The plugins of this process for the bindings and tools that need one set: the default
/// plugins (loadDefaultPlugins), loaded on first use, safely from any thread.
PluginHost& processPlugins();

}  // namespace airshape::plugin
