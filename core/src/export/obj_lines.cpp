// Lines in OBJ: OCCT's OBJ writer writes the triangles of faces only, so stiffeners and
// beams (edges outside faces) are appended to its file as `l` records.
#include "obj_lines.h"

#include <filesystem>
#include <fstream>
#include <string>

#include "format_writers.h"
#include "mesh_lines.h"

namespace airshape::exporting {

namespace {

/// How many vertices an OBJ file has: the lines' vertices are numbered after them.
std::size_t vertexCount(const std::string& path) {
  std::ifstream in(path);
  std::size_t count = 0;
  for (std::string line; std::getline(in, line);) count += line.rfind("v ", 0) == 0;
  return count;
}

}  // namespace

void addLinesToObj(const ExportScene& scene, const std::string& path, const std::string& target) {
  if (!hasLines(scene)) return;
  const bool fromScratch = !std::filesystem::exists(path);
  std::size_t next = fromScratch ? 1 : vertexCount(path) + 1;
  std::ofstream out(path, std::ios::app);
  out.precision(17);
  if (fromScratch) out << "# generator: airshape\n";
  for (const SceneComponent& component : scene.components) {
    const auto lines = polylinesOf(component.shape.shape);
    if (lines.empty()) continue;
    out << "g " << scene.name << '/' << component.name << '\n';
    for (const auto& line : lines) {
      for (const gp_Pnt& p : line) out << "v " << p.X() << ' ' << p.Y() << ' ' << p.Z() << '\n';
      out << 'l';
      for (std::size_t k = 0; k < line.size(); ++k) out << ' ' << next++;
      out << '\n';
    }
  }
  if (!out.flush()) throw cannotWrite("OBJ", target);
}

}  // namespace airshape::exporting
