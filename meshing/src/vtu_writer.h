#pragma once

#include <string>

#include "mesh_tables.h"

namespace airshape::meshing {

/// Writes the mesh as a VTK XML unstructured grid (ASCII): every element as a cell, the cell
/// array "group" with the index of its first physical group, and per group a one-value field
/// array named "group:<name>" holding that index.
void writeVtu(const MeshTables& mesh, const std::string& path);

}  // namespace airshape::meshing
