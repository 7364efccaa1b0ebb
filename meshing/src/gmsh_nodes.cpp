#include "gmsh_nodes.h"

#include <gmsh.h>

namespace airshape::meshing {

Position positionOf(const std::vector<double>& coordinates, std::size_t node) {
  return {coordinates[3 * node], coordinates[3 * node + 1], coordinates[3 * node + 2]};
}

std::map<std::size_t, std::size_t> indicesOfGmshNodes(std::vector<double>& coordinates,
                                                      const std::map<Position, std::size_t>& known) {
  std::vector<std::size_t> tags;
  std::vector<double> positions, parametric;
  gmsh::model::mesh::getNodes(tags, positions, parametric, -1, -1, false, false);
  std::map<std::size_t, std::size_t> indexOfTag;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const Position position{positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    const auto found = known.find(position);
    if (found != known.end()) {
      indexOfTag[tags[i]] = found->second;
    } else {
      indexOfTag[tags[i]] = coordinates.size() / 3;
      coordinates.insert(coordinates.end(), position.begin(), position.end());
    }
  }
  return indexOfTag;
}

std::vector<std::size_t> elementsOfType(int type, const std::map<std::size_t, std::size_t>& indexOfTag) {
  std::vector<std::size_t> elementTags, nodeTags, nodes;
  gmsh::model::mesh::getElementsByType(type, elementTags, nodeTags);
  for (std::size_t tag : nodeTags) nodes.push_back(indexOfTag.at(tag));
  return nodes;
}

}  // namespace airshape::meshing
