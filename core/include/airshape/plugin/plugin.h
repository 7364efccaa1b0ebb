#pragma once

#include <memory>
#include <string>
#include <vector>

#include <boost/dll/alias.hpp>

#include "airshape/component_shapes.h"
#include "airshape/graph/component_graph.h"
#include "airshape/plugin/services.h"
#include "airshape/query/query_registry.h"

/// The plugin ABI of this core. A plugin records the value of the headers it was built
/// against; the host refuses plugins whose value differs from its own. Raise it whenever
/// a change to Plugin, QueryRegistry, Configuration or the generated model breaks plugins.
#ifndef AIRSHAPE_PLUGIN_ABI_VERSION
#define AIRSHAPE_PLUGIN_ABI_VERSION 10
#endif

namespace airshape::plugin {

/// A node type a plugin builds, where its nodes live and what they are for exports and
/// measures (graph::ComponentLocation; docs/plugins.md, "Declaring node types"). A plugin may
/// declare one node type at several places.
using NodeType = graph::ComponentLocation;

/// A plugin another one builds on, in the versions it works with: minimum <= version < below
/// (versions compare number by number: 0.10.0 comes after 0.9.2; an empty bound is open).
struct Requirement {
  std::string plugin;
  std::string minimum;
  std::string below;
};

/// What every plugin implements. See docs/plugins.md for the contract.
class Plugin {
 public:
  virtual ~Plugin() = default;
  virtual std::string name() const = 0;
  virtual std::string version() const = 0;
  /// One line on what the plugin builds.
  virtual std::string description() const = 0;
  /// The node types this plugin builds, each where it lives and what it is.
  virtual std::vector<NodeType> nodeTypes() const = 0;
  /// Adds this plugin's query ops (their owner is this plugin's name).
  virtual void registerQueries(query::QueryRegistry& registry) const = 0;
  /// Adds the builders of the solids of its node types (those it was granted are kept).
  virtual void registerShapeBuilders(ComponentShapes& /*shapes*/) const {}
  /// The plugins this one builds on: the host loads them first and refuses this one, with one
  /// line, when one is missing or of a version outside the range.
  virtual std::vector<Requirement> requirements() const { return {}; }
  /// Offers what other plugins may use of this one (its public interface).
  virtual void offerServices(ServiceRegistry& /*services*/) const {}
  /// Receives what the plugins loaded before it offer (those it requires among them), before
  /// its queries and builders are registered.
  virtual void useServices(const ServiceRegistry& /*services*/) {}
};

/// The plugin ABI version a plugin was compiled with (exported by AIRSHAPE_PLUGIN).
inline int compiledAbiVersion() { return AIRSHAPE_PLUGIN_ABI_VERSION; }

}  // namespace airshape::plugin

/// Exports a plugin class from a shared library: a factory and the ABI version, under the
/// names the host looks for (airshape_create_plugin, airshape_plugin_abi_version).
#define AIRSHAPE_PLUGIN(PluginClass)                                                                    \
  namespace airshape_plugin_export {                                                                    \
  inline std::shared_ptr<airshape::plugin::Plugin> create() { return std::make_shared<PluginClass>(); } \
  inline int abiVersion() { return airshape::plugin::compiledAbiVersion(); }                            \
  }                                                                                                     \
  BOOST_DLL_ALIAS(airshape_plugin_export::create, airshape_create_plugin)                               \
  BOOST_DLL_ALIAS(airshape_plugin_export::abiVersion, airshape_plugin_abi_version)
