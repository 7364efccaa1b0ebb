#include "boundary_layer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/error.h"
#include "mesh_tables.h"
#include "triangle_crossings.h"

namespace airshape::meshing {

namespace {

/// A triangle's unit normal pointing into the fluid (its nodes turn the other way).
gp_Vec intoFluid(const std::vector<double>& coordinates, const std::size_t* triangle) {
  const gp_Pnt a = nodePoint(coordinates, triangle[0]);
  gp_Vec normal =
      gp_Vec(a, nodePoint(coordinates, triangle[2])).Crossed(gp_Vec(a, nodePoint(coordinates, triangle[1])));
  const double length = normal.Magnitude();
  return length > 0 ? normal / length : normal;
}

/// The angle of a triangle at one of its corners (the corner's share of the node's normal).
double angleAt(const std::vector<double>& coordinates, const std::size_t* triangle, int corner) {
  const gp_Pnt at = nodePoint(coordinates, triangle[corner]);
  const gp_Vec toNext(at, nodePoint(coordinates, triangle[(corner + 1) % 3]));
  const gp_Vec toPrevious(at, nodePoint(coordinates, triangle[(corner + 2) % 3]));
  return toNext.Magnitude() > 0 && toPrevious.Magnitude() > 0 ? toNext.Angle(toPrevious) : 0.0;
}

/// How high a direction rises above the least risen of the planes with the given normals.
double leastRise(const gp_Vec& direction, const std::vector<gp_Vec>& normals) {
  double least = 1;
  for (const gp_Vec& normal : normals) least = std::min(least, direction.Dot(normal));
  return least;
}

/// The unit direction that rises most above the least risen of the planes with the given
/// normals (within the plane y = 0 when `inPlane`, the normals then taken as their shadows in
/// it). The best direction makes one, two or three rises equal, so these candidates suffice.
gp_Vec mostRisingDirection(std::vector<gp_Vec> normals, bool inPlane) {
  std::vector<gp_Vec> candidates;
  const auto add = [&](gp_Vec candidate) {
    if (inPlane) candidate.SetY(0);
    if (candidate.Magnitude() > 1e-12) candidates.push_back(candidate / candidate.Magnitude());
  };
  if (inPlane)
    for (gp_Vec& normal : normals) normal.SetY(0);
  for (std::size_t i = 0; i < normals.size(); ++i) {
    add(normals[i]);
    for (std::size_t j = i + 1; j < normals.size(); ++j) {
      const gp_Vec apart = normals[i] - normals[j];  // equal rises: square to the difference
      const gp_Vec square = inPlane ? gp_Vec(apart.Z(), 0, -apart.X()) : normals[i] + normals[j];
      add(square);
      if (inPlane) add(-square);
      for (std::size_t k = j + 1; k < normals.size() && !inPlane; ++k) {
        const gp_Vec& a = normals[i];
        const gp_Vec& b = normals[j];
        const gp_Vec& c = normals[k];
        const double determinant = a.Dot(b.Crossed(c));
        if (std::abs(determinant) > 1e-9) add((b.Crossed(c) + c.Crossed(a) + a.Crossed(b)) / determinant);
      }
    }
  }
  gp_Vec best(0, 0, 0);
  double bestRise = -2;
  for (const gp_Vec& candidate : candidates)
    if (const double rise = leastRise(candidate, normals); rise > bestRise) best = candidate, bestRise = rise;
  return best;
}

/// How far and which way each wall node moves per metre of layer height: the angle-weighted
/// mean of its triangles' normals where that rises well above all of them, else the direction
/// that rises most (at edges that fold sharply); lengthened so that the node rises one metre
/// above its triangles (at most twice, and less at edges sharper than 60 degrees). Zero where
/// no direction rises above all the triangles around a node.
std::map<std::size_t, gp_Vec> directionsOfNodes(const std::vector<double>& coordinates, const Triangles& walls,
                                                const std::unordered_set<std::size_t>& symmetryNodes) {
  std::map<std::size_t, gp_Vec> sums;
  std::map<std::size_t, std::vector<gp_Vec>> normalsAround;
  for (std::size_t triangle = 0; triangle < walls.size(); triangle += 3) {
    const gp_Vec normal = intoFluid(coordinates, &walls[triangle]);
    for (int corner = 0; corner < 3; ++corner) {
      const std::size_t node = walls[triangle + static_cast<std::size_t>(corner)];
      auto [sum, added] = sums.emplace(node, gp_Vec(0, 0, 0));
      sum->second += normal * angleAt(coordinates, &walls[triangle], corner);
      normalsAround[node].push_back(normal);
    }
  }
  for (auto& [node, direction] : sums) {
    const bool inPlane = symmetryNodes.count(node) != 0;  // the layer's side stays in the plane
    const std::vector<gp_Vec>& normals = normalsAround[node];
    if (inPlane) direction.SetY(0);
    if (direction.Magnitude() > 1e-12) direction.Normalize();
    if (leastRise(direction, normals) < 0.5) direction = mostRisingDirection(normals, inPlane);
    const double rise = leastRise(direction, normals);
    direction *= rise > 0 ? 1 / std::max(rise, 0.5) : 0.0;
  }
  return sums;
}

/// Whether the prism's centre lies inside each of its faces' pyramids: each face, cut into
/// triangles around its centre, faces away from the prism's centre (the test finite-volume
/// solvers make: OpenFOAM's checkMesh calls its failure "incorrectly oriented" faces).
bool facesEnclosePrism(const std::vector<double>& coordinates, const std::size_t* n) {
  // Outward faces of Gmsh's prism: the bottom turned, the top, the three sides.
  static const std::vector<std::vector<std::size_t>> faces = {
      {0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  gp_XYZ centre(0, 0, 0);
  for (std::size_t corner = 0; corner < 6; ++corner) centre += nodePoint(coordinates, n[corner]).XYZ() / 6;
  for (const std::vector<std::size_t>& face : faces) {
    gp_XYZ faceCentre(0, 0, 0);
    for (std::size_t corner : face) faceCentre += nodePoint(coordinates, n[corner]).XYZ() / double(face.size());
    for (std::size_t i = 0; i < face.size(); ++i) {
      const gp_XYZ a = nodePoint(coordinates, n[face[i]]).XYZ() - faceCentre;
      const gp_XYZ b = nodePoint(coordinates, n[face[(i + 1) % face.size()]]).XYZ() - faceCentre;
      if (a.Crossed(b).Dot(faceCentre - centre) <= 0) return false;
    }
  }
  return true;
}

/// Whether a prism (Gmsh's order: a triangle, then the one above it) is valid: its Jacobian
/// positive at all six corners, and its faces enclosing its centre.
bool isValidPrism(const std::vector<double>& coordinates, const std::size_t* n) {
  if (!facesEnclosePrism(coordinates, n)) return false;
  for (std::size_t corner = 0; corner < 3; ++corner) {
    const std::size_t next = (corner + 1) % 3, previous = (corner + 2) % 3;
    const gp_Vec up(nodePoint(coordinates, n[corner]), nodePoint(coordinates, n[corner + 3]));
    for (std::size_t level : {0, 3}) {
      const gp_Pnt at = nodePoint(coordinates, n[level + corner]);
      const gp_Vec normal = gp_Vec(at, nodePoint(coordinates, n[level + next]))
                                .Crossed(gp_Vec(at, nodePoint(coordinates, n[level + previous])));
      if (normal.Dot(up) <= 0) return false;
    }
  }
  return true;
}

[[noreturn]] void refuseFold(const std::vector<double>& coordinates, std::size_t node) {
  char where[128];
  std::snprintf(where, sizeof where, "(%.4g, %.4g, %.4g)", coordinates[3 * node], coordinates[3 * node + 1],
                coordinates[3 * node + 2]);
  throw Error(ErrorCode::InvalidArgument, std::string("--boundary-layer: the prisms cannot rise from the wall at ") +
                                              where + ", where it folds onto itself: finer surface elements there " +
                                              "(--size UID=SIZE)");
}

/// The wall's edges on the symmetry plane, each as its triangle runs it.
std::vector<std::pair<std::size_t, std::size_t>> edgesOnPlane(const Triangles& walls,
                                                              const std::unordered_set<std::size_t>& symmetryNodes) {
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for (std::size_t triangle = 0; triangle < walls.size(); triangle += 3)
    for (std::size_t corner = 0; corner < 3; ++corner) {
      const std::size_t a = walls[triangle + corner], b = walls[triangle + (corner + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (std::size_t triangle = 0; triangle < walls.size(); triangle += 3)
    for (std::size_t corner = 0; corner < 3; ++corner) {
      const std::size_t a = walls[triangle + corner], b = walls[triangle + (corner + 1) % 3];
      if (uses[{std::min(a, b), std::max(a, b)}] == 1 && symmetryNodes.count(a) != 0 && symmetryNodes.count(b) != 0)
        edges.emplace_back(a, b);
    }
  return edges;
}

/// Each wall node's shortest edge.
std::unordered_map<std::size_t, double> shortestEdges(const std::vector<double>& coordinates, const Triangles& walls) {
  std::unordered_map<std::size_t, double> shortest;
  for (std::size_t triangle = 0; triangle < walls.size(); triangle += 3)
    for (std::size_t corner = 0; corner < 3; ++corner) {
      const std::size_t a = walls[triangle + corner], b = walls[triangle + (corner + 1) % 3];
      const double length = nodePoint(coordinates, a).Distance(nodePoint(coordinates, b));
      for (std::size_t node : {a, b}) {
        auto [at, added] = shortest.emplace(node, length);
        if (!added) at->second = std::min(at->second, length);
      }
    }
  return shortest;
}

/// The layers' nodes above the wall nodes: the wall node, then one per layer, the layer's
/// heights times the node's share of them.
struct Columns {
  std::unordered_map<std::size_t, std::vector<std::size_t>> above;  // wall node -> nodes, bottom up
  std::unordered_map<std::size_t, double> share;                    // of the asked heights, at most 1
};

void placeColumn(std::vector<double>& coordinates, const std::vector<std::size_t>& column, const gp_Vec& direction,
                 double share, bool onPlane, const BoundaryLayer& layer) {
  const gp_Pnt base = nodePoint(coordinates, column.front());
  double height = 0, step = layer.firstHeight * share;
  for (std::size_t k = 1; k < column.size(); ++k, step *= layer.growth) {
    height += step;
    const gp_Pnt point = base.Translated(direction * height);
    const double placed[3] = {point.X(), onPlane ? 0.0 : point.Y(), point.Z()};  // exactly in the plane
    std::copy(placed, placed + 3, coordinates.begin() + static_cast<long>(3 * column[k]));
  }
}

/// The nodes of the prisms over one wall triangle, bottom layer first, each in Gmsh's order.
std::vector<std::array<std::size_t, 6>> prismsOver(const std::size_t* triangle, const Columns& columns) {
  // The wall triangle's nodes turn out of the fluid; a prism's bottom turns towards its top.
  const std::vector<std::size_t>& a = columns.above.at(triangle[0]);
  const std::vector<std::size_t>& b = columns.above.at(triangle[2]);
  const std::vector<std::size_t>& c = columns.above.at(triangle[1]);
  std::vector<std::array<std::size_t, 6>> prisms;
  for (std::size_t k = 0; k + 1 < a.size(); ++k) prisms.push_back({a[k], b[k], c[k], a[k + 1], b[k + 1], c[k + 1]});
  return prisms;
}

/// The wall nodes of the prisms that turn inside out.
std::unordered_set<std::size_t> nodesUnderInvalidPrisms(const std::vector<double>& coordinates, const Triangles& walls,
                                                        const Columns& columns) {
  std::unordered_set<std::size_t> nodes;
  for (std::size_t triangle = 0; triangle < walls.size(); triangle += 3)
    for (const auto& prism : prismsOver(&walls[triangle], columns))
      if (!isValidPrism(coordinates, prism.data())) nodes.insert(&walls[triangle], &walls[triangle] + 3);
  return nodes;
}

/// The wall nodes under the layer's top triangles that cross another top triangle or a wall.
std::unordered_set<std::size_t> nodesUnderCrossingTops(const std::vector<double>& coordinates, const Triangles& walls,
                                                       const Columns& columns) {
  Triangles wallsAndTops = walls;  // wall triangle k, then its top as triangle k + walls / 3
  for (std::size_t node : walls) wallsAndTops.push_back(columns.above.at(node).back());
  std::unordered_set<std::size_t> nodes;
  const std::size_t wallCount = walls.size() / 3;
  for (std::size_t triangle : crossingTriangles(coordinates, wallsAndTops))
    if (triangle >= wallCount)  // walls crossing walls are the surface mesh's own, not the layer's
      nodes.insert(&walls[3 * (triangle - wallCount)], &walls[3 * (triangle - wallCount)] + 3);
  return nodes;
}

/// How often the layer is thinned (halved) where it folds before it is refused.
constexpr int kThinningRounds = 20;

}  // namespace

PrismLayer growPrismLayer(std::vector<double>& coordinates, const Triangles& walls,
                          const std::unordered_set<std::size_t>& symmetryNodes, const BoundaryLayer& layer) {
  const std::map<std::size_t, gp_Vec> directions = directionsOfNodes(coordinates, walls, symmetryNodes);
  const std::unordered_map<std::size_t, double> shortest = shortestEdges(coordinates, walls);
  Columns columns;
  for (const auto& [node, direction] : directions) {
    if (direction.Magnitude() <= 1e-12) refuseFold(coordinates, node);
    std::vector<std::size_t>& column = columns.above[node];
    column.push_back(node);
    for (int k = 1; k <= layer.count; ++k) column.push_back(coordinates.size() / 3 + static_cast<std::size_t>(k - 1));
    coordinates.resize(coordinates.size() + 3 * static_cast<std::size_t>(layer.count));
    // No taller than half the node's shortest edge: a layer as tall as its triangles are wide folds.
    columns.share[node] = std::min(1.0, 0.5 * shortest.at(node) / (direction.Magnitude() * layer.thickness()));
  }
  // Where prisms turn inside out, or the layer's top crosses itself or a wall (where walls are
  // concave or close), the layer is made thinner at their nodes until none does.
  std::unordered_set<std::size_t> toPlace;
  for (const auto& [node, column] : columns.above) toPlace.insert(node);
  for (int round = 0;; ++round) {
    for (std::size_t node : toPlace)
      placeColumn(coordinates, columns.above[node], directions.at(node), columns.share[node],
                  symmetryNodes.count(node) != 0, layer);
    toPlace = nodesUnderInvalidPrisms(coordinates, walls, columns);
    if (toPlace.empty()) toPlace = nodesUnderCrossingTops(coordinates, walls, columns);
    if (toPlace.empty()) break;
    if (round == kThinningRounds) refuseFold(coordinates, *toPlace.begin());
    for (std::size_t node : toPlace) columns.share[node] /= 2;
  }
  PrismLayer prisms;
  for (std::size_t triangle = 0; triangle < walls.size(); triangle += 3) {
    for (const auto& prism : prismsOver(&walls[triangle], columns))
      prisms.prisms.insert(prisms.prisms.end(), prism.begin(), prism.end());
    const std::size_t* t = &walls[triangle];
    prisms.top.insert(prisms.top.end(),
                      {columns.above[t[0]].back(), columns.above[t[1]].back(), columns.above[t[2]].back()});
  }
  const std::size_t count = static_cast<std::size_t>(layer.count);
  for (const auto& [a, b] : edgesOnPlane(walls, symmetryNodes))
    for (std::size_t k = 0; k < count; ++k)
      prisms.sides.insert(prisms.sides.end(),
                          {columns.above[a][k], columns.above[b][k], columns.above[b][k + 1], columns.above[a][k + 1]});
  for (const auto& [node, column] : columns.above) {
    prisms.topOf[node] = column.back();
    if (columns.share[node] < 1) ++prisms.thinned;
  }
  return prisms;
}

}  // namespace airshape::meshing
