#pragma once

#include <string>

#include "airshape/export/export_scene.h"

namespace airshape::exporting {

/// Adds the scene's lines (edges outside faces: stiffeners and beams, as the mesher's
/// polylines) to the OBJ file OCCT's writer made at `path`, which writes triangles only: a
/// group `<file>/<uID>` per line component, its points as vertices after the file's own and
/// an `l` record per polyline. Without `path` existing (a scene of lines alone, which OCCT
/// does not write) the file is made of the lines alone. Throws Error(WriteFailed) naming
/// `target` when the file cannot be read or written.
void addLinesToObj(const ExportScene& scene, const std::string& path, const std::string& target);

}  // namespace airshape::exporting
