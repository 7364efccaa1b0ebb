#include "stl_writer.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>

#include "airshape/error.h"

namespace airshape::meshing {

namespace {

using Triangle = std::array<std::size_t, 3>;

std::vector<Triangle> trianglesOf(const MeshTables& mesh) {
  std::vector<Triangle> triangles;
  for (const ElementBlock& block : mesh.blocks) {
    if (block.dimension != 2) continue;
    const std::size_t perElement = static_cast<std::size_t>(block.nodesPerElement);
    const bool quadrilateral = block.gmshType == 3 || block.gmshType == 16;
    for (std::size_t element = 0; element < block.entity.size(); ++element) {
      const std::size_t* node = &block.nodes[element * perElement];
      triangles.push_back({node[0], node[1], node[2]});
      if (quadrilateral) triangles.push_back({node[0], node[2], node[3]});
    }
  }
  return triangles;
}

void put(std::ofstream& out, float value) { out.write(reinterpret_cast<const char*>(&value), sizeof value); }

}  // namespace

void writeStl(const MeshTables& mesh, const std::string& path) {
  const std::vector<Triangle> triangles = trianglesOf(mesh);
  if (triangles.empty()) throw Error(ErrorCode::InvalidArgument, "STL: the mesh has no surface elements", path);
  std::ofstream out(path, std::ios::binary);
  char header[80] = "airshape mesh";
  out.write(header, sizeof header);
  const std::uint32_t count = static_cast<std::uint32_t>(triangles.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  for (const Triangle& triangle : triangles) {
    std::array<std::array<double, 3>, 3> corner{};
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t axis = 0; axis < 3; ++axis) corner[c][axis] = mesh.coordinates[3 * triangle[c] + axis];
    std::array<double, 3> u{}, v{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      u[axis] = corner[1][axis] - corner[0][axis];
      v[axis] = corner[2][axis] - corner[0][axis];
    }
    const std::array<double, 3> normal{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    for (double component : normal) put(out, static_cast<float>(length > 0 ? component / length : 0));
    for (const auto& point : corner)
      for (double value : point) put(out, static_cast<float>(value));
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), sizeof attributes);
  }
  out.close();
  if (!out) throw Error(ErrorCode::WriteFailed, "cannot write the STL file", path);
}

}  // namespace airshape::meshing
