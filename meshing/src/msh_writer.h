#pragma once

#include <string>

#include "mesh_tables.h"

namespace airshape::meshing {

/// Writes the mesh as Gmsh MSH 4.1, ASCII (OpenFOAM's gmshToFoam reads only ASCII): the
/// physical groups named, one entity per surface, volume or curve with its groups, each node
/// on the first entity whose elements use it.
void writeMsh(const MeshTables& mesh, const std::string& path);

}  // namespace airshape::meshing
