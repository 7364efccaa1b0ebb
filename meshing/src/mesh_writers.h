#pragma once

#include <string>

#include "airshape/meshing/mesh_format.h"
#include "mesh_tables.h"

namespace airshape::meshing {

/// Writes a mesh to `path` in `format`, complete or not at all (every format by our own writer,
/// so that all hold the same elements turned the same way).
void writeMesh(const MeshTables& tables, const std::string& path, MeshFormat format);

}  // namespace airshape::meshing
