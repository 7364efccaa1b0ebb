#pragma once

#include <TopoDS_Shape.hxx>

#include "gmsh_model.h"
#include "mesh_tables.h"

namespace airshape::meshing {

/// Turns the elements of each surface so that their normals point as the face's normal in the
/// shape does (outwards on a solid, into the fluid on a CFD domain's walls): Gmsh meshes a
/// surface as its geometry runs, whatever the face's orientation in the solid.
void orientLikeFaces(MeshTables& tables, const TopoDS_Shape& shape, const ImportedShape& imported);

}  // namespace airshape::meshing
