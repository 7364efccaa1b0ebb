#include "vtu_writer.h"

#include <fstream>
#include <map>

#include "airshape/error.h"

namespace airshape::meshing {

namespace {

/// VTK's cell type of a Gmsh element type (node orders: vtkNodePlace).
int vtkCellType(int gmshType) {
  static const std::map<int, int> types = {{1, 3},  {2, 5},  {3, 9},  {4, 10}, {5, 12}, {6, 13},
                                           {7, 14}, {8, 21}, {9, 22}, {15, 1}, {16, 23}};
  const auto found = types.find(gmshType);
  if (found == types.end())
    throw Error(ErrorCode::InvalidArgument, "VTU: no VTK cell for Gmsh element type " + std::to_string(gmshType));
  return found->second;
}

/// XML's special characters in a name written as an attribute.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::size_t vtkNodePlace(int gmshType, std::size_t place) {
  static const std::size_t prism[6] = {0, 2, 1, 3, 5, 4};
  return gmshType == 6 ? prism[place] : place;
}

void writeVtu(const MeshTables& mesh, const std::string& path) {
  std::ofstream out(path);
  out.precision(17);
  std::size_t cells = 0;
  for (const ElementBlock& block : mesh.blocks) cells += block.entity.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid>\n<FieldData>\n";
  for (std::size_t group = 0; group < mesh.groups.size(); ++group)
    out << "<DataArray type=\"Int32\" Name=\"group:" << escaped(mesh.groups[group].name)
        << "\" NumberOfTuples=\"1\" format=\"ascii\">" << group << "</DataArray>\n";
  out << "</FieldData>\n<Piece NumberOfPoints=\"" << mesh.nodeCount() << "\" NumberOfCells=\"" << cells << "\">\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < mesh.coordinates.size(); i += 3)
    out << mesh.coordinates[i] << ' ' << mesh.coordinates[i + 1] << ' ' << mesh.coordinates[i + 2] << '\n';
  out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const ElementBlock& block : mesh.blocks)
    for (std::size_t i = 0; i < block.nodes.size(); ++i) {
      const std::size_t per = static_cast<std::size_t>(block.nodesPerElement), first = i - i % per;
      out << block.nodes[first + vtkNodePlace(block.gmshType, i % per)] << ((i + 1) % per == 0 ? '\n' : ' ');
    }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for (const ElementBlock& block : mesh.blocks)
    for (std::size_t element = 0; element < block.entity.size(); ++element)
      out << (offset += static_cast<std::size_t>(block.nodesPerElement)) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const ElementBlock& block : mesh.blocks)
    for (std::size_t element = 0; element < block.entity.size(); ++element) out << vtkCellType(block.gmshType) << '\n';
  out << "</DataArray>\n</Cells>\n<CellData Scalars=\"group\">\n"
         "<DataArray type=\"Int32\" Name=\"group\" format=\"ascii\">\n";
  for (const ElementBlock& block : mesh.blocks)
    for (std::size_t entity : block.entity) out << mesh.entities[entity].groups.front() << '\n';
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"part\" format=\"ascii\">\n";
  for (const ElementBlock& block : mesh.blocks)
    for (std::size_t entity : block.entity) {
      const std::vector<int>& groups = mesh.entities[entity].groups;
      out << (groups.size() > 1 ? groups[1] : -1) << '\n';
    }
  out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  out.close();
  if (!out) throw Error(ErrorCode::WriteFailed, "cannot write the VTU file", path);
}

}  // namespace airshape::meshing
