#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "airshape/meshing/mesh_options.h"
#include "gmsh_model.h"
#include "labelled_shape.h"

namespace airshape::meshing {

/// The element sizes of a mesh, metres.
struct Sizes {
  double surface = 0;   ///< largest on the aircraft's surfaces
  double minimum = 0;   ///< smallest anywhere
  double refined = 0;   ///< along trailing edges and where components meet
  double farfield = 0;  ///< on the far field of a CFD domain
  double reach = 0;     ///< the distance from the aircraft at which the fluid's elements reach the far-field size
};

/// The sizes the options ask for, or the defaults from the aircraft's length and the far
/// field's distance (0 without one). Throws Error(InvalidArgument) when the smallest size
/// exceeds the largest.
Sizes sizesFor(const MeshOptions& options, double length, double farfieldDistance);

/// Tells Gmsh the sizes: the largest and smallest, by curvature, finer along trailing edges
/// and the curves where components meet, per component as asked, and in a CFD domain growing
/// from the surface size at the aircraft to the far-field size at the boundary.
void setSizeFields(const TopoDS_Shape& shape, const std::vector<FaceLabel>& labels, const ImportedShape& imported,
                   const MeshOptions& options, const Sizes& sizes);

/// Tells Gmsh the sizes of a fluid alone, in a model of its own: growing from the surface size
/// at the given entities (`list`: "FacesList" or "EdgesList") to the far-field size, nothing
/// taken from the meshes of the fluid's boundary.
void setFluidSizes(const std::string& list, const std::vector<double>& tags, const Sizes& sizes);

}  // namespace airshape::meshing
