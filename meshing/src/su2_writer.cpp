#include "su2_writer.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>

#include "airshape/error.h"
#include "vtu_writer.h"

namespace airshape::meshing {

namespace {

/// SU2's (VTK's) element type of a Gmsh element type.
int su2Type(int gmshType) {
  static const std::map<int, int> types = {{1, 3}, {2, 5}, {3, 9}, {4, 10}, {5, 12}, {6, 13}, {7, 14}};
  const auto found = types.find(gmshType);
  if (found == types.end())
    throw Error(ErrorCode::InvalidArgument,
                "SU2: no element for Gmsh element type " + std::to_string(gmshType) + " (SU2 takes linear elements)");
  return found->second;
}

/// A marker's name as SU2's configuration files can name it: no white space.
std::string markerName(std::string name) {
  std::replace_if(
      name.begin(), name.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
  return name;
}

void writeElement(std::ofstream& out, const ElementBlock& block, std::size_t element) {
  out << su2Type(block.gmshType);
  const std::size_t perElement = static_cast<std::size_t>(block.nodesPerElement);
  for (std::size_t node = 0; node < perElement; ++node)
    out << ' ' << block.nodes[element * perElement + vtkNodePlace(block.gmshType, node)];
}

}  // namespace

void writeSu2(const MeshTables& mesh, const std::string& path) {
  int highest = 0;
  for (const ElementBlock& block : mesh.blocks) highest = std::max(highest, block.dimension);
  std::ofstream out(path);
  out.precision(17);
  std::size_t elements = 0;
  for (const ElementBlock& block : mesh.blocks)
    if (block.dimension == highest) elements += block.entity.size();
  out << "NDIME= 3\nNELEM= " << elements << '\n';
  std::size_t number = 0;
  for (const ElementBlock& block : mesh.blocks)
    if (block.dimension == highest)
      for (std::size_t element = 0; element < block.entity.size(); ++element) {
        writeElement(out, block, element);
        out << ' ' << number++ << '\n';
      }
  out << "NPOIN= " << mesh.nodeCount() << '\n';
  for (std::size_t node = 0; node < mesh.nodeCount(); ++node)
    out << mesh.coordinates[3 * node] << ' ' << mesh.coordinates[3 * node + 1] << ' ' << mesh.coordinates[3 * node + 2]
        << ' ' << node << '\n';
  const auto elementsOfGroups = mesh.elementsOfGroups();
  std::size_t markers = 0;
  for (const MeshGroup& group : mesh.groups) markers += group.dimension == highest - 1 || highest == 2;
  out << "NMARK= " << markers << '\n';
  for (std::size_t group = 0; group < mesh.groups.size(); ++group) {
    if (!(mesh.groups[group].dimension == highest - 1 || highest == 2)) continue;
    out << "MARKER_TAG= " << markerName(mesh.groups[group].name) << "\nMARKER_ELEMS= " << elementsOfGroups[group].size()
        << '\n';
    for (const auto& [block, element] : elementsOfGroups[group]) {
      writeElement(out, mesh.blocks[block], element);
      out << '\n';
    }
  }
  out.close();
  if (!out) throw Error(ErrorCode::WriteFailed, "cannot write the SU2 file", path);
}

}  // namespace airshape::meshing
