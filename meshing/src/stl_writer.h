#pragma once

#include <string>

#include "mesh_tables.h"

namespace airshape::meshing {

/// Writes the mesh's triangles (quadrilaterals split in two) as binary STL, each once.
void writeStl(const MeshTables& mesh, const std::string& path);

}  // namespace airshape::meshing
