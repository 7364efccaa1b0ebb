#include "triangle_crossings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace airshape::meshing {

namespace {

using Vector = std::array<double, 3>;

Vector minus(const Vector& a, const Vector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vector cross(const Vector& a, const Vector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Triangle {
  std::array<Vector, 3> corners;
  Vector low, high;
};

/// Whether the segment p-q passes through the triangle's inside (Möller and Trumbore's
/// test), touching at an end or along an edge not counted.
bool segmentCrosses(const Vector& p, const Vector& q, const Triangle& triangle) {
  constexpr double margin = 1e-9;
  const Vector edge1 = minus(triangle.corners[1], triangle.corners[0]);
  const Vector edge2 = minus(triangle.corners[2], triangle.corners[0]);
  const Vector direction = minus(q, p);
  const Vector h = cross(direction, edge2);
  const double determinant = dot(edge1, h);
  if (std::abs(determinant) < 1e-300) return false;  // parallel: such contacts Gmsh tells apart itself
  const Vector s = minus(p, triangle.corners[0]);
  const double u = dot(s, h) / determinant;
  if (u <= margin || u >= 1 - margin) return false;
  const Vector r = cross(s, edge1);
  const double v = dot(direction, r) / determinant;
  if (v <= margin || u + v >= 1 - margin) return false;
  const double along = dot(edge2, r) / determinant;
  return along > margin && along < 1 - margin;
}

bool cross(const Triangle& a, const Triangle& b) {
  for (int corner = 0; corner < 3; ++corner)
    if (segmentCrosses(a.corners[corner], a.corners[(corner + 1) % 3], b) ||
        segmentCrosses(b.corners[corner], b.corners[(corner + 1) % 3], a))
      return true;
  return false;
}

bool overlapping(const Triangle& a, const Triangle& b) {
  for (int axis = 0; axis < 3; ++axis)
    if (a.low[axis] > b.high[axis] || b.low[axis] > a.high[axis]) return false;
  return true;
}

bool shareNode(const std::size_t* a, const std::size_t* b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a[i] == b[j]) return true;
  return false;
}

}  // namespace

std::vector<std::size_t> crossingTriangles(const std::vector<double>& coordinates,
                                           const std::vector<std::size_t>& triangles) {
  const std::size_t count = triangles.size() / 3;
  std::vector<Triangle> boxes(count);
  std::vector<double> extents;
  for (std::size_t t = 0; t < count; ++t) {
    Triangle& triangle = boxes[t];
    for (int c = 0; c < 3; ++c) {
      const std::size_t node = triangles[3 * t + static_cast<std::size_t>(c)];
      triangle.corners[static_cast<std::size_t>(c)] = {coordinates[3 * node], coordinates[3 * node + 1],
                                                       coordinates[3 * node + 2]};
    }
    for (int axis = 0; axis < 3; ++axis) {
      triangle.low[axis] = std::min({triangle.corners[0][axis], triangle.corners[1][axis], triangle.corners[2][axis]});
      triangle.high[axis] = std::max({triangle.corners[0][axis], triangle.corners[1][axis], triangle.corners[2][axis]});
      extents.push_back(triangle.high[axis] - triangle.low[axis]);
    }
  }
  if (count == 0) return {};
  // Cells about twice a typical triangle: each triangle lands in a few, each cell holds a few.
  std::nth_element(extents.begin(), extents.begin() + static_cast<long>(extents.size() / 2), extents.end());
  const double cell = std::max(2 * extents[extents.size() / 2], 1e-12);
  std::map<std::array<long, 3>, std::vector<std::size_t>> cells;
  for (std::size_t t = 0; t < count; ++t) {
    std::array<long, 3> low{}, high{};
    for (int axis = 0; axis < 3; ++axis) {
      low[axis] = static_cast<long>(std::floor(boxes[t].low[axis] / cell));
      high[axis] = static_cast<long>(std::floor(boxes[t].high[axis] / cell));
    }
    for (long x = low[0]; x <= high[0]; ++x)
      for (long y = low[1]; y <= high[1]; ++y)
        for (long z = low[2]; z <= high[2]; ++z) cells[{x, y, z}].push_back(t);
  }
  std::vector<bool> crossing(count, false);
  for (const auto& [where, members] : cells)
    for (std::size_t i = 0; i < members.size(); ++i)
      for (std::size_t j = i + 1; j < members.size(); ++j) {
        const std::size_t a = members[i], b = members[j];
        if ((crossing[a] && crossing[b]) || !overlapping(boxes[a], boxes[b]) ||
            shareNode(&triangles[3 * a], &triangles[3 * b]))
          continue;
        if (cross(boxes[a], boxes[b])) crossing[a] = crossing[b] = true;
      }
  std::vector<std::size_t> result;
  for (std::size_t t = 0; t < count; ++t)
    if (crossing[t]) result.push_back(t);
  return result;
}

}  // namespace airshape::meshing
