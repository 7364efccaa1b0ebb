#pragma once

#include <string>

#include "mesh_tables.h"

namespace airshape::meshing {

/// Writes the mesh in SU2's native format: the elements of the highest dimension as the
/// mesh's elements (NDIME 3), and each physical group of the dimension below as a marker
/// (MARKER_TAG its name, white space written as _).
void writeSu2(const MeshTables& mesh, const std::string& path);

}  // namespace airshape::meshing
