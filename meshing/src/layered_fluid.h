#pragma once

#include <string>
#include <vector>

#include "airshape/meshing/mesh_options.h"
#include "mesh_tables.h"
#include "size_fields.h"

namespace airshape::meshing {

/// The mesh of a CFD domain whose fluid begins with prism layers on the aircraft's walls and
/// goes on in tetrahedra, from the domain's surface mesh in Gmsh's current model (with its size
/// fields) and as read from it: `surface` holds the triangles of the aircraft (turned out of the
/// fluid, as the fluid solid's faces), of "farfield" and of "symmetry", and the volume group
/// "fluid" still without elements. The symmetry plane is meshed again around the layers' sides.
/// The tetrahedra are made in the current model, which then holds them (for Gmsh's measure of
/// their quality). Throws Error when the layer folds or Gmsh cannot fill the fluid.
/// Where the layer had to be thinner than asked, a line is added to `notes`.
MeshTables layeredFluid(const MeshTables& surface, const BoundaryLayer& layer, const Sizes& sizes,
                        std::vector<std::string>& notes);

}  // namespace airshape::meshing
