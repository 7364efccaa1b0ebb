#pragma once

#include <string>

#include "airshape/export/export_scene.h"

namespace airshape::exporting {

/// Adds the scene's lines (edges outside faces: stiffeners and beams, as the mesher's
/// polylines) to the glTF or GLB file OCCT's writer made at `path`, which writes triangles
/// only: each line component's node (by its uID; a new one under the root where OCCT wrote
/// none) gets a mesh of LINE_STRIP primitives, y up as the triangles are. Without `path`
/// existing (a scene of lines alone, which OCCT does not write) the file is made from scratch.
/// A .gltf's buffer is its side file (.bin), which grows too. Throws Error(WriteFailed)
/// naming `target` when a file cannot be read back or written.
void addLinesToGltf(const ExportScene& scene, const std::string& path, const std::string& target, bool binary);

}  // namespace airshape::exporting
