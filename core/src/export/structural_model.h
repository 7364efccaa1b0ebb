#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "airshape/export/export_options.h"
#include "airshape/export/export_scene.h"

namespace airshape {
class Configuration;
}

namespace airshape::exporting {

/// What the structural models are made of: each wanted component that holds structure and its
/// structure's components, in build order (built beforehand, in parallel, with progress).
std::vector<std::size_t> structuralModelComponents(const Configuration& configuration, const ExportOptions& options);

/// The structural models `export --structure` writes (ExportOptions::structure): one per
/// component that holds structure, named "<uID> structure", its faces named as the host's and
/// the structure's faces they came from. Structure that fails to build is left out and said in
/// `leftOut`. `step` is told before each model is joined (which takes seconds on a large model).
/// Throws Error naming the host when the faces cannot be joined.
std::vector<SceneComponent> structuralModels(const Configuration& configuration, const ExportOptions& options,
                                             std::vector<std::string>& leftOut,
                                             const std::function<void(const std::string&)>& step);

}  // namespace airshape::exporting
