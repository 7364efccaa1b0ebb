#include "layered_fluid.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>

#include <gmsh.h>

#include "airshape/error.h"
#include "boundary_layer.h"
#include "fluid_domain.h"
#include "gmsh_nodes.h"
#include "gmsh_session.h"
#include "symmetry_plane.h"

namespace airshape::meshing {

namespace {

/// The surface mesh's triangles sorted by what they bound, each with its entity.
struct DomainSurface {
  Triangles walls, farfield, symmetry;
  std::vector<std::size_t> wallEntity, farfieldEntity;  // per triangle
  std::optional<std::size_t> symmetryEntity, fluidEntity;
};

bool inGroup(const MeshTables& tables, const MeshEntity& entity, const std::string& name) {
  return std::any_of(entity.groups.begin(), entity.groups.end(),
                     [&](int group) { return tables.groups[static_cast<std::size_t>(group)].name == name; });
}

DomainSurface sortedSurface(const MeshTables& surface) {
  DomainSurface sorted;
  enum class Bounds { Wall, Farfield, Symmetry };
  std::vector<Bounds> bounds(surface.entities.size(), Bounds::Wall);  // what each entity's triangles bound
  for (std::size_t entity = 0; entity < surface.entities.size(); ++entity) {
    if (surface.entities[entity].dimension == 3 && !sorted.fluidEntity) sorted.fluidEntity = entity;
    if (inGroup(surface, surface.entities[entity], "symmetry")) {
      bounds[entity] = Bounds::Symmetry;
      if (!sorted.symmetryEntity) sorted.symmetryEntity = entity;
    } else if (inGroup(surface, surface.entities[entity], "farfield")) {
      bounds[entity] = Bounds::Farfield;
    }
  }
  if (!sorted.fluidEntity) throw Error(ErrorCode::InvalidArgument, "--boundary-layer: the mesh has no fluid volume");
  for (const ElementBlock& block : surface.blocks) {
    if (block.dimension != 2) continue;
    if (block.gmshType != kTriangle)
      throw Error(ErrorCode::InvalidArgument, "--boundary-layer grows from triangles, not from " + block.name);
    for (std::size_t element = 0; element < block.entity.size(); ++element) {
      const std::size_t entity = block.entity[element];
      const auto first = block.nodes.begin() + static_cast<long>(3 * element);
      if (bounds[entity] == Bounds::Symmetry) {
        sorted.symmetry.insert(sorted.symmetry.end(), first, first + 3);
      } else if (bounds[entity] == Bounds::Farfield) {
        sorted.farfield.insert(sorted.farfield.end(), first, first + 3);
        sorted.farfieldEntity.push_back(entity);
      } else {
        sorted.walls.insert(sorted.walls.end(), first, first + 3);
        sorted.wallEntity.push_back(entity);
      }
    }
  }
  return sorted;
}

/// The tetrahedra of the fluid beyond the boundary layer, meshed in Gmsh's current model, whose
/// size fields still hold: its fluid volume is replaced by one bounded by the layer's top
/// (`top`, new nodes), the symmetry plane meshed again (`symmetry`) and the far field's surfaces
/// as they are. `tags`: each of our nodes' tag in the model, for those it has.
std::vector<std::size_t> tetrahedraBeyondLayer(std::vector<double>& coordinates, const std::vector<std::size_t>& tags,
                                               const Triangles& top, const Triangles& symmetry,
                                               const std::vector<int>& farfieldSurfaces) {
  std::vector<std::size_t> tetrahedra;
  callGmsh("meshing the fluid beyond the boundary layer", [&] {
    std::vector<std::size_t> tagOf = tags;
    std::vector<bool> inModel(coordinates.size() / 3, false);
    std::fill(inModel.begin(), inModel.begin() + static_cast<long>(tags.size()), true);
    std::size_t nextTag = tags.empty() ? 1 : *std::max_element(tags.begin(), tags.end()) + 1;
    while (tagOf.size() < coordinates.size() / 3) tagOf.push_back(nextTag++);
    std::vector<int> bounding;
    for (const Triangles* triangles : {&top, &symmetry}) {
      if (triangles->empty()) continue;
      const int surface = gmsh::model::addDiscreteEntity(2);
      std::vector<std::size_t> newTags, elementNodes;
      std::vector<double> positions;
      for (std::size_t node : *triangles) {
        elementNodes.push_back(tagOf[node]);
        if (inModel[node]) continue;
        inModel[node] = true;
        newTags.push_back(tagOf[node]);
        const Position position = positionOf(coordinates, node);
        positions.insert(positions.end(), position.begin(), position.end());
      }
      gmsh::model::mesh::addNodes(2, surface, newTags, positions);
      gmsh::model::mesh::addElementsByType(surface, kTriangle, {}, elementNodes);
      bounding.push_back(surface);
    }
    bounding.insert(bounding.end(), farfieldSurfaces.begin(), farfieldSurfaces.end());
    gmsh::vectorpair volumes;
    gmsh::model::getEntities(volumes, 3);
    int volumeTag = 1;
    for (const auto& [dimension, tag] : volumes) volumeTag = std::max(volumeTag, tag + 1);
    gmsh::model::removeEntities(volumes);
    gmsh::model::geo::addVolume({gmsh::model::geo::addSurfaceLoop(bounding)}, volumeTag);
    gmsh::model::geo::synchronize();
    generateTetrahedra();
    // Gmsh numbers the nodes anew after meshing: ours are found by their positions.
    std::map<Position, std::size_t> known;
    for (std::size_t node = 0; node < coordinates.size() / 3; ++node) known[positionOf(coordinates, node)] = node;
    tetrahedra = elementsOfType(kTetrahedron, indicesOfGmshNodes(coordinates, known));
  });
  return tetrahedra;
}

/// Turns elements (first three corners' normal) to face -y: out of the half domain y >= 0.
void turnOutOfHalfDomain(const std::vector<double>& coordinates, std::vector<std::size_t>& nodes, std::size_t per) {
  for (std::size_t first = 0; first < nodes.size(); first += per) {
    const Position a = positionOf(coordinates, nodes[first]), b = positionOf(coordinates, nodes[first + 1]),
                   c = positionOf(coordinates, nodes[first + 2]);
    const double normalY = (c[0] - a[0]) * (b[2] - a[2]) - (b[0] - a[0]) * (c[2] - a[2]);
    if (normalY > 0)
      std::reverse(nodes.begin() + static_cast<long>(first + 1), nodes.begin() + static_cast<long>(first + per));
  }
}

void addBlock(MeshTables& tables, int type, const char* name, int dimension, const std::vector<std::size_t>& nodes,
              const std::vector<std::size_t>& entities) {
  if (entities.empty()) return;
  ElementBlock block;
  block.gmshType = type;
  block.name = name;
  block.dimension = dimension;
  block.nodesPerElement = static_cast<int>(nodes.size() / entities.size());
  block.nodes = nodes;
  block.entity = entities;
  tables.blocks.push_back(std::move(block));
}

/// Drops the nodes no element uses (the symmetry plane's before it was meshed again) and
/// numbers the rest from 0 in their order.
void dropUnusedNodes(MeshTables& tables) {
  std::vector<std::size_t> newIndex(tables.nodeCount(), SIZE_MAX);
  for (const ElementBlock& block : tables.blocks)
    for (std::size_t node : block.nodes) newIndex[node] = 0;
  std::vector<double> kept;
  for (std::size_t node = 0; node < newIndex.size(); ++node) {
    if (newIndex[node] == SIZE_MAX) continue;
    newIndex[node] = kept.size() / 3;
    kept.insert(kept.end(), tables.coordinates.begin() + static_cast<long>(3 * node),
                tables.coordinates.begin() + static_cast<long>(3 * node + 3));
  }
  for (ElementBlock& block : tables.blocks)
    for (std::size_t& node : block.nodes) node = newIndex[node];
  tables.coordinates = std::move(kept);
}

}  // namespace

MeshTables layeredFluid(const MeshTables& surface, const BoundaryLayer& layer, const Sizes& sizes,
                        std::vector<std::string>& notes) {
  const DomainSurface sorted = sortedSurface(surface);
  MeshTables mesh;
  mesh.coordinates = surface.coordinates;
  mesh.entities = surface.entities;
  mesh.groups = surface.groups;
  const std::unordered_set<std::size_t> symmetryNodes(sorted.symmetry.begin(), sorted.symmetry.end());
  const PrismLayer prisms = growPrismLayer(mesh.coordinates, sorted.walls, symmetryNodes, layer);
  if (prisms.thinned > 0)
    notes.push_back("--boundary-layer: thinner than asked at " + std::to_string(prisms.thinned) + " of " +
                    std::to_string(prisms.topOf.size()) +
                    " wall nodes, where the wall's elements are shorter than twice the layer, it folds sharply, or the "
                    "layer's top would cross itself or a wall");
  Triangles symmetry;
  std::vector<std::size_t> sides = prisms.sides;
  if (sorted.symmetryEntity) {
    symmetry = remeshedSymmetryPlane(mesh.coordinates, sorted.symmetry, prisms.topOf, sizes);
    turnOutOfHalfDomain(mesh.coordinates, symmetry, 3);
    turnOutOfHalfDomain(mesh.coordinates, sides, 4);
  }
  std::set<int> farfieldSurfaces;
  for (std::size_t entity : sorted.farfieldEntity) farfieldSurfaces.insert(surface.entities[entity].tag);
  std::vector<std::size_t> tetrahedra;
  try {
    tetrahedra = tetrahedraBeyondLayer(mesh.coordinates, surface.gmshTags, prisms.top, symmetry,
                                       std::vector<int>(farfieldSurfaces.begin(), farfieldSurfaces.end()));
  } catch (const Error& error) {  // most likely the layer's top crosses itself where the wall is concave
    throw Error(error.code(), error.message() + " (with --boundary-layer: its top may cross itself or another " +
                                  "component's where walls are close or concave; a thinner layer may do)");
  }

  Triangles boundary = sorted.walls;
  boundary.insert(boundary.end(), sorted.farfield.begin(), sorted.farfield.end());
  boundary.insert(boundary.end(), symmetry.begin(), symmetry.end());
  std::vector<std::size_t> boundaryEntities = sorted.wallEntity;
  boundaryEntities.insert(boundaryEntities.end(), sorted.farfieldEntity.begin(), sorted.farfieldEntity.end());
  boundaryEntities.insert(boundaryEntities.end(), symmetry.size() / 3, sorted.symmetryEntity.value_or(0));
  addBlock(mesh, kTriangle, "Triangle 3", 2, boundary, boundaryEntities);
  addBlock(mesh, kQuadrilateral, "Quadrilateral 4", 2, sides,
           std::vector<std::size_t>(sides.size() / 4, sorted.symmetryEntity.value_or(0)));
  addBlock(mesh, kPrism, "Prism 6", 3, prisms.prisms,
           std::vector<std::size_t>(prisms.prisms.size() / 6, *sorted.fluidEntity));
  addBlock(mesh, kTetrahedron, "Tetrahedron 4", 3, tetrahedra,
           std::vector<std::size_t>(tetrahedra.size() / 4, *sorted.fluidEntity));
  dropUnusedNodes(mesh);
  return mesh;
}

}  // namespace airshape::meshing
