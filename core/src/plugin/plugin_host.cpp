#include "airshape/plugin/plugin_host.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

#include <dlfcn.h>

#include <boost/dll/import.hpp>
#include <boost/dll/shared_library.hpp>

#include "airshape/core_module.h"
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

/// A version's numbers: "0.10.2" -> {0, 10, 2}; what is no number counts as 0.
std::vector<long> versionNumbers(const std::string& version) {
  std::vector<long> numbers;
  std::stringstream parts(version);
  for (std::string part; std::getline(parts, part, '.');) numbers.push_back(std::strtol(part.c_str(), nullptr, 10));
  return numbers;
}

/// -1, 0 or 1 as version a comes before, with or after version b (missing numbers are 0).
int compareVersions(const std::string& a, const std::string& b) {
  std::vector<long> x = versionNumbers(a), y = versionNumbers(b);
  x.resize(std::max(x.size(), y.size()), 0);
  y.resize(x.size(), 0);
  return x < y ? -1 : x > y ? 1 : 0;
}

bool versionInRange(const std::string& version, const Requirement& requirement) {
  return (requirement.minimum.empty() || compareVersions(version, requirement.minimum) >= 0) &&
         (requirement.below.empty() || compareVersions(version, requirement.below) < 0);
}

}  // namespace

std::string describeRange(const Requirement& requirement) {
  std::string bounds;
  if (!requirement.minimum.empty()) bounds += ">= " + requirement.minimum;
  if (!requirement.below.empty()) bounds += (bounds.empty() ? "< " : ", < ") + requirement.below;
  return bounds.empty() ? "" : " (version " + bounds + ")";
}

PluginHost::PluginHost() { registerCoreQueries(queries_); }

PluginHost::~PluginHost() {
  shapes_ = ComponentShapes();  // builders and ops are plugin code too: they go first
  queries_ = query::QueryRegistry();
  services_ = ServiceRegistry();
  pending_.clear();
  while (!plugins_.empty()) plugins_.pop_back();
}

std::string PluginHost::coreLibraryFolder() { return airshape::coreLibraryFolder(); }

void PluginHost::loadDefaultPlugins() {
  openFolder(coreLibraryFolder(), false);
  if (const char* extra = std::getenv("AIRSHAPE_PLUGIN_PATH")) openPluginPath(extra);
  registerReadyPlugins();
}

void PluginHost::openPluginPath(const std::string& path) {
  std::stringstream list(path);
  for (std::string item; std::getline(list, item, ':');) {
    if (item.empty()) continue;
    std::error_code error;
    if (fs::is_directory(item, error)) {
      openFolder(item, true);
    } else if (fs::exists(item, error)) {
      open(item);
    } else {
      messages_.push_back("AIRSHAPE_PLUGIN_PATH: " + item + ": no such file or folder");
    }
  }
}

void PluginHost::loadFolder(const std::string& folder, bool anyName) {
  openFolder(folder, anyName);
  registerReadyPlugins();
}

void PluginHost::openFolder(const std::string& folder, bool anyName) {
  for (const fs::path& path : sortedEntries(folder)) {
    const std::string fileName = path.filename().string();
    if (!isSharedLibrary(path)) continue;
    if (!anyName && fileName.rfind(kBuiltInPrefix, 0) != 0) continue;
    open(path.string());
  }
}

bool PluginHost::loadFile(const std::string& file) {
  const bool opened = open(file);
  registerReadyPlugins();
  return opened && std::none_of(pending_.begin(), pending_.end(),
                                [&](const LoadedPlugin& p) { return p.file == fs::weakly_canonical(file).string(); });
}

bool PluginHost::open(const std::string& file) {
  const std::string canonical = fs::weakly_canonical(file).string();
  for (const auto* list : {&plugins_, &pending_})
    for (const auto& loaded : *list)
      if (loaded.file == canonical) return true;  // the same file found twice
  std::shared_ptr<Plugin> plugin;
  try {
    // Every symbol resolved now: a plugin linked against a library it lacks is refused here
    // with one line, instead of ending the process at its first call.
    boost::dll::shared_library library(canonical, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local);
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
    // A plugin stays loaded until the process ends: what it made may outlive the host that
    // loaded it (an error thrown in it and caught after the host is gone, a shape whose OCCT
    // types it instantiated, cached results), and would then point into unmapped code.
    dlopen(canonical.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    // import_alias keeps the library loaded for as long as the returned function exists;
    // the plugin object's deleter holds that function, and with it the library.
    auto factory = boost::dll::import_alias<std::shared_ptr<Plugin>()>(library, "airshape_create_plugin");
    std::shared_ptr<Plugin> created = factory();
    plugin = std::shared_ptr<Plugin>(created.get(), [created, factory](Plugin*) mutable { created.reset(); });
  } catch (const std::exception& error) {
    messages_.push_back(canonical + ": cannot be loaded as a plugin (" + std::string(error.what()) + "); skipped");
    return false;
  }
  pending_.push_back({canonical, plugin, {}});
  return true;
}

std::optional<std::string> PluginHost::unmetRequirement(const Plugin& plugin) const {
  for (const Requirement& requirement : plugin.requirements()) {
    const auto provider = std::find_if(plugins_.begin(), plugins_.end(), [&](const LoadedPlugin& loaded) {
      return loaded.plugin->name() == requirement.plugin;
    });
    const std::string range = describeRange(requirement);
    if (provider == plugins_.end()) return "requires plugin " + requirement.plugin + range + ", which is not loaded";
    if (!versionInRange(provider->plugin->version(), requirement))
      return "requires plugin " + requirement.plugin + range + ", but version " + provider->plugin->version() +
             " is loaded";
  }
  return std::nullopt;
}

void PluginHost::registerReadyPlugins() {
  // Plugins whose requirements are registered register in turn, until none is left that can.
  for (bool progress = true; progress;) {
    progress = false;
    for (auto candidate = pending_.begin(); candidate != pending_.end();) {
      if (unmetRequirement(*candidate->plugin)) {
        ++candidate;
        continue;
      }
      LoadedPlugin ready = std::move(*candidate);
      candidate = pending_.erase(candidate);
      registerPlugin(std::move(ready));
      progress = true;
    }
  }
  for (const LoadedPlugin& refused : pending_)
    messages_.push_back(refused.file + ": plugin " + refused.plugin->name() + " " + *unmetRequirement(*refused.plugin) +
                        "; skipped");
  pending_.clear();
}

void PluginHost::registerPlugin(LoadedPlugin loaded) {
  const std::shared_ptr<Plugin>& plugin = loaded.plugin;
  std::set<std::string> granted, refused;  // a node type may be declared at several places
  for (const NodeType& type : plugin->nodeTypes()) {
    const std::string owner = pluginFor(type.nodeType);
    if (!owner.empty()) {
      if (refused.insert(type.nodeType).second)
        messages_.push_back(loaded.file + ": plugin " + plugin->name() + " claims node type '" + type.nodeType +
                            "', which plugin " + owner + " builds already; the claim is ignored");
      continue;
    }
    loaded.nodeTypes.push_back(type);
    granted.insert(type.nodeType);
  }
  plugin->useServices(services_);
  plugin->offerServices(services_);
  query::QueryRegistry ops;
  plugin->registerQueries(ops);
  for (const query::Op* op : ops.ops()) {
    query::Op copy = *op;
    copy.owner = plugin->name();
    try {
      queries_.add(std::move(copy));
    } catch (const Error& error) {
      messages_.push_back(loaded.file + ": " + error.message());
    }
  }
  ComponentShapes offered;
  plugin->registerShapeBuilders(offered);
  for (const ComponentCutOuts& cutOuts : offered.cutOuts()) shapes_.addCutOuts(cutOuts);
  for (const std::string& type : granted) {  // only for the node types it was granted
    if (const ShapeBuilder* builder = offered.find(type)) shapes_.add(type, *builder);
    if (const ShapeBuilder* detailed = offered.findDetailed(type)) shapes_.addDetailed(type, *detailed);
    if (const ComponentMotion* motion = offered.findMotion(type)) shapes_.addMotion(type, *motion);
    if (const std::string* why = offered.declined(type)) shapes_.decline(type, *why);
  }
  plugins_.push_back(std::move(loaded));
}

std::vector<graph::ComponentLocation> PluginHost::componentLocations() const {
  std::vector<graph::ComponentLocation> declared;
  for (const auto& loaded : plugins_) declared.insert(declared.end(), loaded.nodeTypes.begin(), loaded.nodeTypes.end());
  return graph::resolveLocations(declared);
}

std::string PluginHost::pluginFor(const std::string& nodeType) const {
  for (const auto& loaded : plugins_)
    for (const NodeType& type : loaded.nodeTypes)
      if (type.nodeType == nodeType) return loaded.plugin->name();
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
