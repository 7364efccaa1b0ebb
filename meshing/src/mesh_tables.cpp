#include "mesh_tables.h"

#include <algorithm>
#include <map>
#include <unordered_map>

#include <gmsh.h>

#include "airshape/error.h"
#include "gmsh_session.h"

namespace airshape::meshing {

namespace {

/// The entities in physical groups (in Gmsh's order of dimension and tag), each with the
/// groups that hold it, and the groups in the order of their tags.
std::vector<MeshEntity> entitiesInGroups(std::vector<MeshGroup>& groups) {
  gmsh::vectorpair physical;
  gmsh::model::getPhysicalGroups(physical);
  std::sort(physical.begin(), physical.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });  // by tag: as added
  std::map<std::pair<int, int>, std::vector<int>> held;
  for (const auto& [dimension, tag] : physical) {
    std::string name;
    gmsh::model::getPhysicalName(dimension, tag, name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dimension, tag, entities);
    for (int entity : entities) held[{dimension, entity}].push_back(static_cast<int>(groups.size()));
    groups.push_back({name, dimension});
  }
  std::vector<MeshEntity> entities;
  for (const auto& [entity, holding] : held) entities.push_back({entity.first, entity.second, holding});
  return entities;
}

ElementBlock& blockOfType(MeshTables& tables, int type) {
  for (ElementBlock& block : tables.blocks)
    if (block.gmshType == type) return block;
  ElementBlock block;
  block.gmshType = type;
  int order = 0, primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, block.name, block.dimension, order, block.nodesPerElement, local,
                                          primary);
  tables.blocks.push_back(block);
  return tables.blocks.back();
}

}  // namespace

std::vector<std::vector<std::pair<std::size_t, std::size_t>>> MeshTables::elementsOfGroups() const {
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> elements(groups.size());
  for (std::size_t block = 0; block < blocks.size(); ++block)
    for (std::size_t element = 0; element < blocks[block].entity.size(); ++element)
      for (int group : entities[blocks[block].entity[element]].groups)
        elements[static_cast<std::size_t>(group)].emplace_back(block, element);
  return elements;
}

MeshTables meshTablesFromGmsh() {
  MeshTables tables;
  callGmsh("reading the mesh", [&] {
    std::vector<std::size_t> nodeTags;
    std::vector<double> parametric;
    gmsh::model::mesh::getNodes(nodeTags, tables.coordinates, parametric, -1, -1, false, false);
    std::unordered_map<std::size_t, std::size_t> indexOfTag;
    for (std::size_t index = 0; index < nodeTags.size(); ++index) indexOfTag[nodeTags[index]] = index;
    tables.gmshTags = nodeTags;
    tables.entities = entitiesInGroups(tables.groups);
    for (std::size_t entity = 0; entity < tables.entities.size(); ++entity) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elementTags, elementNodes;
      gmsh::model::mesh::getElements(types, elementTags, elementNodes, tables.entities[entity].dimension,
                                     tables.entities[entity].tag);
      for (std::size_t t = 0; t < types.size(); ++t) {
        ElementBlock& block = blockOfType(tables, types[t]);
        for (std::size_t node : elementNodes[t]) block.nodes.push_back(indexOfTag.at(node));
        block.entity.insert(block.entity.end(), elementTags[t].size(), entity);
      }
    }
  });
  return tables;
}

const std::vector<int>& reversedNodeOrder(int gmshType) {
  static const std::map<int, std::vector<int>> orders = {
      {1, {1, 0}},       {8, {1, 0, 2}},          {2, {0, 2, 1}},
      {3, {0, 3, 2, 1}}, {9, {0, 2, 1, 5, 4, 3}}, {16, {0, 3, 2, 1, 7, 6, 5, 4}},
  };
  const auto found = orders.find(gmshType);
  if (found == orders.end())
    throw Error(ErrorCode::InvalidArgument, "no reversed order for Gmsh element type " + std::to_string(gmshType));
  return found->second;
}

}  // namespace airshape::meshing
