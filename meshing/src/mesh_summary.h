#pragma once

#include <string>

#include "airshape/meshing/mesher.h"
#include "mesh_tables.h"

namespace airshape::meshing {

/// The summary of the mesh in Gmsh's model: its nodes, its elements by type, and the worst
/// quality of its elements of the highest dimension as Gmsh's AnalyseMeshQuality measures
/// it (the inverse condition number).
MeshSummary summaryOfGmshMesh(const std::string& name, const MeshTables& tables);

}  // namespace airshape::meshing
