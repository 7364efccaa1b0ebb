#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace airshape::meshing {

/// Gmsh's numbers of the element types a fluid mesh holds.
constexpr int kTriangle = 2, kQuadrilateral = 3, kTetrahedron = 4, kPrism = 6;

/// A node's x, y and z, compared bit for bit.
using Position = std::array<double, 3>;

/// The position of node `node` in a coordinates table (x, y, z per node).
Position positionOf(const std::vector<double>& coordinates, std::size_t node);

/// Gmsh's current model's nodes as our node indices: the `known` nodes found by their exact
/// position (Gmsh keeps the coordinates it is given, not always the tags), others added to
/// `coordinates`.
std::map<std::size_t, std::size_t> indicesOfGmshNodes(std::vector<double>& coordinates,
                                                      const std::map<Position, std::size_t>& known);

/// The elements of one Gmsh type in Gmsh's current model, as our node indices.
std::vector<std::size_t> elementsOfType(int type, const std::map<std::size_t, std::size_t>& indexOfTag);

}  // namespace airshape::meshing
