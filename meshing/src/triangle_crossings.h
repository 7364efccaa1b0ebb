#pragma once

#include <cstddef>
#include <vector>

namespace airshape::meshing {

/// The triangles (three node indices each, into `coordinates`: x, y, z per node) that cross
/// another of the set: an edge of one passes through the inside of the other. Triangles that
/// share a node are not compared (they meet there by construction). Each crossing triangle's
/// index (its first node's place / 3) once, in increasing order.
std::vector<std::size_t> crossingTriangles(const std::vector<double>& coordinates,
                                           const std::vector<std::size_t>& triangles);

}  // namespace airshape::meshing
