#include "abaqus_writer.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>

#include "airshape/error.h"

namespace airshape::meshing {

namespace {

struct AbaqusType {
  const char* name;
  std::vector<int> order;  ///< Gmsh's node at each of Abaqus's places
};

const AbaqusType& abaqusType(int gmshType) {
  static const std::map<int, AbaqusType> types = {
      {1, {"B31", {0, 1}}},
      {8, {"B32", {0, 2, 1}}},  // Abaqus puts the middle node between the ends
      {2, {"S3", {0, 1, 2}}},
      {3, {"S4", {0, 1, 2, 3}}},
      {9, {"S6", {0, 1, 2, 3, 4, 5}}},
      {16, {"S8", {0, 1, 2, 3, 4, 5, 6, 7}}},
      {4, {"C3D4", {0, 1, 2, 3}}},
      {6, {"C3D6", {0, 1, 2, 3, 4, 5}}},
      {11, {"C3D10", {0, 1, 2, 3, 4, 5, 6, 7, 9, 8}}},  // edges (1,3) and (2,3) swap places
  };
  const auto found = types.find(gmshType);
  if (found == types.end())
    throw Error(ErrorCode::InvalidArgument, "INP: no Abaqus element for Gmsh element type " + std::to_string(gmshType));
  return found->second;
}

/// Data lines of at most 16 numbers, as Abaqus reads them.
void writeList(std::ofstream& out, const std::vector<std::size_t>& numbers) {
  for (std::size_t i = 0; i < numbers.size(); ++i)
    out << numbers[i] << ((i + 1) % 16 == 0 || i + 1 == numbers.size() ? "\n" : ", ");
}

}  // namespace

std::string abaqusSetName(const std::string& name) {
  std::string set;
  for (char c : name) set += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
  if (set.empty() || !std::isalpha(static_cast<unsigned char>(set.front()))) set = "G_" + set;
  return set.substr(0, 80);
}

void writeAbaqus(const MeshTables& mesh, const std::string& path) {
  std::ofstream out(path);
  out.precision(12);  // CalculiX reads numbers of at most 20 characters
  out << "*HEADING\nwritten by airshape mesh\n*NODE\n";
  for (std::size_t node = 0; node < mesh.nodeCount(); ++node)
    out << node + 1 << ", " << mesh.coordinates[3 * node] << ", " << mesh.coordinates[3 * node + 1] << ", "
        << mesh.coordinates[3 * node + 2] << '\n';
  std::vector<std::size_t> firstNumber;  // of each block's elements
  std::size_t number = 1;
  for (const ElementBlock& block : mesh.blocks) {
    const AbaqusType& type = abaqusType(block.gmshType);
    firstNumber.push_back(number);
    out << "*ELEMENT, TYPE=" << type.name << '\n';
    const std::size_t perElement = static_cast<std::size_t>(block.nodesPerElement);
    for (std::size_t element = 0; element < block.entity.size(); ++element, ++number) {
      out << number;
      for (int place : type.order)
        out << ", " << block.nodes[element * perElement + static_cast<std::size_t>(place)] + 1;
      out << '\n';
    }
  }
  const auto elementsOfGroups = mesh.elementsOfGroups();
  for (std::size_t group = 0; group < mesh.groups.size(); ++group) {
    std::vector<std::size_t> elements;
    std::set<std::size_t> nodes;
    for (const auto& [block, element] : elementsOfGroups[group]) {
      elements.push_back(firstNumber[block] + element);
      const ElementBlock& of = mesh.blocks[block];
      const std::size_t perElement = static_cast<std::size_t>(of.nodesPerElement);
      for (std::size_t node = 0; node < perElement; ++node) nodes.insert(of.nodes[element * perElement + node] + 1);
    }
    if (elements.empty()) continue;
    std::sort(elements.begin(), elements.end());
    const std::string name = abaqusSetName(mesh.groups[group].name);
    out << "*ELSET, ELSET=" << name << '\n';
    writeList(out, elements);
    out << "*NSET, NSET=" << name << '\n';
    writeList(out, std::vector<std::size_t>(nodes.begin(), nodes.end()));
  }
  out.close();
  if (!out) throw Error(ErrorCode::WriteFailed, "cannot write the INP file", path);
}

}  // namespace airshape::meshing
