#pragma once

#include <cstddef>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "airshape/meshing/mesh_options.h"

namespace airshape::meshing {

/// Triangles as node indices, three per triangle.
using Triangles = std::vector<std::size_t>;

/// The prisms grown from a CFD domain's walls into the fluid.
struct PrismLayer {
  /// Six nodes per prism, in Gmsh's order: a triangle of one layer, then the triangle above it.
  std::vector<std::size_t> prisms;
  /// The outermost layer's triangles, where the tetrahedra begin.
  Triangles top;
  /// Four nodes per quadrilateral: the layers' sides standing in the symmetry plane y = 0.
  std::vector<std::size_t> sides;
  /// Each wall node's node above it on the outermost layer.
  std::unordered_map<std::size_t, std::size_t> topOf;
  /// How many wall nodes have a thinner layer than asked (see growPrismLayer).
  std::size_t thinned = 0;
};

/// Grows `layer` from the wall triangles into the fluid and adds its nodes to `coordinates`
/// (x, y, z per node). The walls' triangles are turned out of the fluid, as the faces of the
/// fluid's solid are. Each node rises along the mean of its triangles' normals (or, where the
/// wall folds sharply, the direction that rises most above them all), far enough that each
/// layer keeps its height over the triangles around it; `symmetryNodes` move within the plane
/// y = 0. The layer is thinner than asked at a node where it would be taller than half the
/// node's shortest edge, and halved again where a prism would turn inside out or the layer's
/// top would cross itself or a wall. Throws Error naming the place where no direction rises
/// above all triangles, or where halving twenty times does not help.
PrismLayer growPrismLayer(std::vector<double>& coordinates, const Triangles& walls,
                          const std::unordered_set<std::size_t>& symmetryNodes, const BoundaryLayer& layer);

}  // namespace airshape::meshing
