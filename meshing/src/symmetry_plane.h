#pragma once

#include <cstddef>
#include <unordered_map>
#include <vector>

#include "boundary_layer.h"
#include "size_fields.h"

namespace airshape::meshing {

/// The symmetry plane of a half domain meshed again between the far field's edge and the prism
/// layers' sides standing in it: its boundary runs through the nodes of `plane`'s boundary,
/// each edge one element, the wall's nodes replaced by the layer's top nodes above them
/// (`topOf`); new nodes are added to `coordinates`. Gmsh meshes it in a model of its own and
/// comes back to the current one. Throws Error when the plane's boundary touches itself.
Triangles remeshedSymmetryPlane(std::vector<double>& coordinates, const Triangles& plane,
                                const std::unordered_map<std::size_t, std::size_t>& topOf, const Sizes& sizes);

}  // namespace airshape::meshing
