#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <gp_Pnt.hxx>

namespace airshape::meshing {

/// One of Gmsh's model entities with elements: a surface, a volume, a curve.
struct MeshEntity {
  int dimension = 0;
  int tag = 0;              ///< Gmsh's tag of the entity
  std::vector<int> groups;  ///< the physical groups that hold it (indices into MeshTables::groups)
};

/// The elements of one type in a mesh.
struct ElementBlock {
  int gmshType = 0;   ///< Gmsh's element type number
  std::string name;   ///< Gmsh's name of the type, "Triangle 3", "Tetrahedron 4", ...
  int dimension = 0;  ///< 1 lines, 2 shells, 3 solids
  int nodesPerElement = 0;
  std::vector<std::size_t> nodes;   ///< node indices (from 0), nodesPerElement per element
  std::vector<std::size_t> entity;  ///< per element: its entity (index into MeshTables::entities)
};

/// A physical group: its name and dimension.
struct MeshGroup {
  std::string name;
  int dimension = 0;
};

/// A mesh as plain tables, for the writers: nodes numbered from 0, elements by type, the
/// entities they lie on and the physical groups those are in.
struct MeshTables {
  std::vector<double> coordinates;    ///< x, y, z of each node
  std::vector<std::size_t> gmshTags;  ///< each node's tag in Gmsh's model, when the tables were read from it
  std::vector<ElementBlock> blocks;
  std::vector<MeshEntity> entities;
  std::vector<MeshGroup> groups;

  std::size_t nodeCount() const { return coordinates.size() / 3; }
  /// Each group's elements as (block, element in the block), in block order.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> elementsOfGroups() const;
};

/// Node `node` of a coordinates table (x, y, z per node) as a point.
inline gp_Pnt nodePoint(const std::vector<double>& coordinates, std::size_t node) {
  return gp_Pnt(coordinates[3 * node], coordinates[3 * node + 1], coordinates[3 * node + 2]);
}

/// The tables of the mesh in Gmsh's model: the elements of every entity in a physical group,
/// each once however many groups hold it.
MeshTables meshTablesFromGmsh();

/// Gmsh's node order of an element of `gmshType` with its orientation turned (its normal
/// reversed): which node goes to each place.
const std::vector<int>& reversedNodeOrder(int gmshType);

}  // namespace airshape::meshing
