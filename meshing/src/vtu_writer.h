#pragma once

#include <cstddef>
#include <string>

#include "mesh_tables.h"

namespace airshape::meshing {

/// Which of Gmsh's nodes of an element of `gmshType` goes to `place` in VTK's (and SU2's)
/// node order: a prism's base turns the other way in VTK (its normal away from the top).
std::size_t vtkNodePlace(int gmshType, std::size_t place);

/// Writes the mesh as a VTK XML unstructured grid (ASCII): every element as a cell, the cell
/// arrays "group" with the index of its first physical group (its component, its structural
/// model) and "part" with its second (its named face, its structural element; -1 if none),
/// and per group a one-value field array named "group:<name>" holding that index.
void writeVtu(const MeshTables& mesh, const std::string& path);

}  // namespace airshape::meshing
