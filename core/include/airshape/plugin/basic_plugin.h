#pragma once

#include <string>
#include <utility>
#include <vector>

#include "airshape/plugin/plugin.h"

namespace airshape::plugin {

/// A Plugin whose name, version, description and node types are fixed at construction.
/// Plugins derive from it and override registerQueries() when they add ops.
class BasicPlugin : public Plugin {
 public:
  BasicPlugin(std::string name, std::string version, std::string description, std::vector<NodeType> nodeTypes,
              std::vector<Requirement> requirements = {})
      : name_(std::move(name)),
        version_(std::move(version)),
        description_(std::move(description)),
        nodeTypes_(std::move(nodeTypes)),
        requirements_(std::move(requirements)) {}

  std::string name() const override { return name_; }
  std::string version() const override { return version_; }
  std::string description() const override { return description_; }
  std::vector<NodeType> nodeTypes() const override { return nodeTypes_; }
  void registerQueries(query::QueryRegistry&) const override {}
  std::vector<Requirement> requirements() const override { return requirements_; }

 private:
  std::string name_;
  std::string version_;
  std::string description_;
  std::vector<NodeType> nodeTypes_;
  std::vector<Requirement> requirements_;
};

}  // namespace airshape::plugin
