#pragma once

#include <string>

#include "airshape/export/export_scene.h"

namespace airshape::exporting {

/// Writes the scene with OCCT's XCAF-based writer of `format` (step, iges, gltf, glb or obj),
/// which lives in libairshape_export_xde.so, loaded on first use and kept (xde_writers.cpp
/// says why). Throws Error naming `target` when it cannot write, or the module's path when
/// the module cannot be loaded.
void writeWithXcaf(const std::string& format, const ExportScene& scene, const std::string& path,
                   const std::string& target);

}  // namespace airshape::exporting
