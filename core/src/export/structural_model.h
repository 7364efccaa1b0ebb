#pragma once

#include <vector>

#include "airshape/export/export_options.h"
#include "airshape/export/export_scene.h"

namespace airshape {
class Configuration;
}

namespace airshape::exporting {

/// The structural models `export --structure` writes (ExportOptions::structure): one per
/// component that holds structure, named "<uID> structure", its faces named as the host's and
/// the structure's faces they came from. Structure that fails to build is left out and said in
/// `leftOut`. Throws Error naming the host when the faces cannot be joined.
std::vector<SceneComponent> structuralModels(const Configuration& configuration, const ExportOptions& options,
                                             std::vector<std::string>& leftOut);

}  // namespace airshape::exporting
