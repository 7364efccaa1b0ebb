#pragma once

#include "airshape/meshing/mesh_options.h"
#include "airshape/named_shape.h"

namespace airshape::meshing {

/// The aircraft's length: the longest side of its bounding box.
double aircraftLength(const TopoDS_Shape& aircraft);

/// The fluid between a labelled aircraft and the far field: a box or a sphere around it, or
/// with `symmetry` its half y >= 0, the aircraft cut out. The boundary's faces are labelled
/// "farfield" and "symmetry", the aircraft's keep their labels. Throws Error when the cut
/// fails.
NamedShape fluidDomain(const NamedShape& aircraft, const Farfield& farfield, bool symmetry);

/// How far the far field lies from the aircraft's box, metres.
double farfieldDistance(const Farfield& farfield, double length);

/// Fills the volumes of Gmsh's current model with tetrahedra, their surfaces meshed.
void generateTetrahedra();

}  // namespace airshape::meshing
