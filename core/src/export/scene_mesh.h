#pragma once

#include "airshape/export/export_options.h"
#include "airshape/export/export_scene.h"

namespace airshape::exporting {

/// Triangulates every face of every component of a scene and gives each edge outside the
/// faces (a stiffener's line) its polyline (both stored in the scene's own copies of the shapes),
/// with the options' deflections; components already meshed (for an earlier output) are left
/// as they are. Throws Error naming the face when one cannot be triangulated.
void triangulate(const ExportScene& scene, const ExportOptions& options);

}  // namespace airshape::exporting
