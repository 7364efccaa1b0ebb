#include "msh_writer.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <limits>

#include "airshape/error.h"

namespace airshape::meshing {

namespace {

/// Per entity: the nodes placed on it (each node on the first entity whose elements use it)
/// and its bounding box.
struct EntityNodes {
  std::vector<std::size_t> nodes;
  std::array<double, 6> box{std::numeric_limits<double>::max(),    std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::max(),    std::numeric_limits<double>::lowest(),
                            std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
};

std::vector<EntityNodes> nodesOfEntities(const MeshTables& mesh) {
  std::vector<EntityNodes> entities(mesh.entities.size());
  std::vector<bool> placed(mesh.nodeCount(), false);
  for (const ElementBlock& block : mesh.blocks)
    for (std::size_t i = 0; i < block.nodes.size(); ++i) {
      const std::size_t node = block.nodes[i];
      EntityNodes& entity = entities[block.entity[i / static_cast<std::size_t>(block.nodesPerElement)]];
      for (int axis = 0; axis < 3; ++axis) {
        const double value = mesh.coordinates[3 * node + static_cast<std::size_t>(axis)];
        entity.box[static_cast<std::size_t>(axis)] = std::min(entity.box[static_cast<std::size_t>(axis)], value);
        entity.box[static_cast<std::size_t>(axis) + 3] =
            std::max(entity.box[static_cast<std::size_t>(axis) + 3], value);
      }
      if (!placed[node]) entity.nodes.push_back(node);
      placed[node] = true;
    }
  return entities;
}

void writeEntities(std::ofstream& out, const MeshTables& mesh, const std::vector<EntityNodes>& nodes) {
  std::array<std::size_t, 4> count{};
  for (const MeshEntity& entity : mesh.entities) ++count[static_cast<std::size_t>(entity.dimension)];
  out << "$Entities\n" << count[0] << ' ' << count[1] << ' ' << count[2] << ' ' << count[3] << '\n';
  for (int dimension = 0; dimension <= 3; ++dimension)
    for (std::size_t index = 0; index < mesh.entities.size(); ++index) {
      const MeshEntity& entity = mesh.entities[index];
      if (entity.dimension != dimension) continue;
      const std::array<double, 6>& box = nodes[index].box;
      out << entity.tag << ' ' << box[0] << ' ' << box[1] << ' ' << box[2];
      if (dimension > 0) out << ' ' << box[3] << ' ' << box[4] << ' ' << box[5];
      out << ' ' << entity.groups.size();
      for (int group : entity.groups) out << ' ' << group + 1;
      out << (dimension > 0 ? " 0\n" : "\n");  // no bounding entities: the mesh needs none
    }
  out << "$EndEntities\n";
}

}  // namespace

void writeMsh(const MeshTables& mesh, const std::string& path) {
  std::ofstream out(path);
  out.precision(17);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" << mesh.groups.size() << '\n';
  for (std::size_t group = 0; group < mesh.groups.size(); ++group)
    out << mesh.groups[group].dimension << ' ' << group + 1 << " \"" << mesh.groups[group].name << "\"\n";
  out << "$EndPhysicalNames\n";
  const std::vector<EntityNodes> nodes = nodesOfEntities(mesh);
  writeEntities(out, mesh, nodes);
  // Nodes numbered 1, 2, ... in the order they are written: OpenFOAM's gmshToFoam takes the
  // n-th node written for node n.
  std::vector<std::size_t> tagOf(mesh.nodeCount(), 0);
  std::size_t placed = 0;
  for (const EntityNodes& entity : nodes)
    for (std::size_t node : entity.nodes) tagOf[node] = ++placed;
  out << "$Nodes\n" << mesh.entities.size() << ' ' << placed << " 1 " << placed << '\n';
  for (std::size_t index = 0; index < mesh.entities.size(); ++index) {
    out << mesh.entities[index].dimension << ' ' << mesh.entities[index].tag << " 0 " << nodes[index].nodes.size()
        << '\n';
    for (std::size_t node : nodes[index].nodes) out << tagOf[node] << '\n';
    for (std::size_t node : nodes[index].nodes)
      out << mesh.coordinates[3 * node] << ' ' << mesh.coordinates[3 * node + 1] << ' '
          << mesh.coordinates[3 * node + 2] << '\n';
  }
  out << "$EndNodes\n";
  // One element block per entity and type.
  std::size_t blocks = 0, elements = 0;
  std::vector<std::vector<std::vector<std::size_t>>> byEntity(
      mesh.entities.size(), std::vector<std::vector<std::size_t>>(mesh.blocks.size()));
  for (std::size_t block = 0; block < mesh.blocks.size(); ++block)
    for (std::size_t element = 0; element < mesh.blocks[block].entity.size(); ++element, ++elements)
      byEntity[mesh.blocks[block].entity[element]][block].push_back(element);
  for (const auto& entity : byEntity)
    for (const auto& ofType : entity) blocks += !ofType.empty();
  out << "$Elements\n" << blocks << ' ' << elements << " 1 " << elements << '\n';
  std::size_t number = 0;
  for (std::size_t entity = 0; entity < byEntity.size(); ++entity)
    for (std::size_t block = 0; block < mesh.blocks.size(); ++block) {
      if (byEntity[entity][block].empty()) continue;
      const ElementBlock& of = mesh.blocks[block];
      out << mesh.entities[entity].dimension << ' ' << mesh.entities[entity].tag << ' ' << of.gmshType << ' '
          << byEntity[entity][block].size() << '\n';
      const std::size_t perElement = static_cast<std::size_t>(of.nodesPerElement);
      for (std::size_t element : byEntity[entity][block]) {
        out << ++number;
        for (std::size_t node = 0; node < perElement; ++node)
          out << ' ' << tagOf[of.nodes[element * perElement + node]];
        out << '\n';
      }
    }
  out << "$EndElements\n";
  out.close();
  if (!out) throw Error(ErrorCode::WriteFailed, "cannot write the MSH file", path);
}

}  // namespace airshape::meshing
