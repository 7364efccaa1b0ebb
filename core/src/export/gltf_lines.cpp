// Lines in glTF: OCCT's glTF writer writes the triangles of faces only, so stiffeners
// and beams (edges outside faces) are added to its file afterwards as LINE_STRIP primitives.
#include "gltf_lines.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "format_writers.h"
#include "mesh_lines.h"

namespace airshape::exporting {

namespace {

using Json = nlohmann::json;

/// A glTF file in memory: its JSON and its one buffer's bytes.
struct GltfFile {
  Json json;
  std::string buffer;
};

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr int kLineStrip = 3;
constexpr int kFloat = 5126;
constexpr int kArrayBuffer = 34962;

std::string fileBytes(const std::filesystem::path& path, const std::string& target) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) throw cannotWrite("glTF (its file could not be read back)", target);
  return bytes.str();
}

std::uint32_t word(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

void appendWord(std::string& bytes, std::uint32_t value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

GltfFile readGlb(const std::filesystem::path& path, const std::string& target) {
  const std::string bytes = fileBytes(path, target);
  if (bytes.size() < 12 || word(bytes, 0) != kGlbMagic) throw cannotWrite("GLB (not a GLB file)", target);
  GltfFile file;
  for (std::size_t at = 12; at + 8 <= bytes.size();) {
    const std::uint32_t length = word(bytes, at), type = word(bytes, at + 4);
    if (at + 8 + length > bytes.size()) throw cannotWrite("GLB (a chunk runs past its end)", target);
    if (type == kJsonChunk) file.json = Json::parse(bytes.substr(at + 8, length));
    if (type == kBinChunk) file.buffer = bytes.substr(at + 8, length);
    at += 8 + length;
  }
  return file;
}

void writeGlb(const std::filesystem::path& path, GltfFile file, const std::string& target) {
  std::string json = file.json.dump();
  json.append((4 - json.size() % 4) % 4, ' ');
  file.buffer.append((4 - file.buffer.size() % 4) % 4, '\0');
  std::string bytes;
  appendWord(bytes, kGlbMagic);
  appendWord(bytes, 2);
  appendWord(bytes,
             static_cast<std::uint32_t>(12 + 8 + json.size() + (file.buffer.empty() ? 0 : 8 + file.buffer.size())));
  appendWord(bytes, static_cast<std::uint32_t>(json.size()));
  appendWord(bytes, kJsonChunk);
  bytes += json;
  if (!file.buffer.empty()) {
    appendWord(bytes, static_cast<std::uint32_t>(file.buffer.size()));
    appendWord(bytes, kBinChunk);
    bytes += file.buffer;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  if (!out.flush()) throw cannotWrite("GLB", target);
}

/// The side file a .gltf keeps its buffer in, named after it where it has none yet.
std::filesystem::path bufferPath(const std::filesystem::path& path, const Json& json) {
  if (json.contains("buffers") && !json["buffers"].empty() && json["buffers"][0].contains("uri"))
    return path.parent_path() / json["buffers"][0]["uri"].get<std::string>();
  return path.parent_path() / (path.stem().string() + ".bin");
}

GltfFile readGltf(const std::filesystem::path& path, const std::string& target) {
  GltfFile file;
  file.json = Json::parse(fileBytes(path, target));
  if (file.json.contains("buffers") && !file.json["buffers"].empty())
    file.buffer = fileBytes(bufferPath(path, file.json), target);
  return file;
}

void writeGltfFiles(const std::filesystem::path& path, const GltfFile& file, const std::string& target) {
  std::ofstream bin(bufferPath(path, file.json), std::ios::binary | std::ios::trunc);
  bin << file.buffer;
  std::ofstream json(path, std::ios::trunc);
  json << file.json.dump();
  if (!bin.flush() || !json.flush()) throw cannotWrite("glTF", target);
}

/// What OCCT would have written for a scene without triangles: the root node named after the
/// configuration, nothing else.
GltfFile emptyGltf(const ExportScene& scene) {
  GltfFile file;
  file.json = {{"asset", {{"version", "2.0"}, {"generator", "airshape"}}},
               {"scene", 0},
               {"scenes", Json::array({{{"nodes", {0}}}})},
               {"nodes", Json::array({{{"name", scene.name}}})}};
  return file;
}

/// A shape's lines turned y up (glTF) from z up (CPACS), as OCCT turns the triangles.
std::vector<std::vector<std::array<float, 3>>> linesOf(const TopoDS_Shape& shape) {
  std::vector<std::vector<std::array<float, 3>>> lines;
  for (const std::vector<gp_Pnt>& polyline : polylinesOf(shape)) {
    std::vector<std::array<float, 3>> line;
    for (const gp_Pnt& p : polyline)
      line.push_back({static_cast<float>(p.X()), static_cast<float>(p.Z()), static_cast<float>(-p.Y())});
    lines.push_back(std::move(line));
  }
  return lines;
}

/// Appends a line's points to the buffer, with their view and accessor (bounds included, as
/// glTF requires of positions); its accessor's index.
int appendPositions(GltfFile& file, const std::vector<std::array<float, 3>>& points) {
  file.buffer.append((4 - file.buffer.size() % 4) % 4, '\0');
  const std::size_t offset = file.buffer.size();
  std::array<float, 3> low, high;
  low.fill(std::numeric_limits<float>::max());
  high.fill(std::numeric_limits<float>::lowest());
  for (const auto& p : points) {
    file.buffer.append(reinterpret_cast<const char*>(p.data()), sizeof p);
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  }
  Json& views = file.json["bufferViews"];
  views.push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", file.buffer.size() - offset}, {"target", kArrayBuffer}});
  Json& accessors = file.json["accessors"];
  accessors.push_back({{"bufferView", views.size() - 1},
                       {"componentType", kFloat},
                       {"count", points.size()},
                       {"type", "VEC3"},
                       {"min", low},
                       {"max", high}});
  return static_cast<int>(accessors.size() - 1);
}

/// The node named `name`; a new one under the root node where there is none.
Json& nodeNamed(GltfFile& file, const std::string& name) {
  Json& nodes = file.json["nodes"];
  for (Json& node : nodes)
    if (node.value("name", "") == name) return node;
  nodes.push_back({{"name", name}});
  const std::size_t root = file.json["scenes"][0]["nodes"][0].get<std::size_t>();
  nodes[root]["children"].push_back(nodes.size() - 1);
  return nodes.back();
}

/// The material of lines: a dark blue, so that they stand out on the light skins.
int lineMaterial(GltfFile& file) {
  Json& materials = file.json["materials"];
  materials.push_back(
      {{"name", "line"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {0.12, 0.25, 0.55, 1.0}}, {"metallicFactor", 0.0}}}});
  return static_cast<int>(materials.size() - 1);
}

}  // namespace

void addLinesToGltf(const ExportScene& scene, const std::string& path, const std::string& target, bool binary) {
  if (!hasLines(scene)) return;
  const std::filesystem::path file(path);
  GltfFile gltf;
  try {
    gltf = !std::filesystem::exists(file) ? emptyGltf(scene) : binary ? readGlb(file, target) : readGltf(file, target);
  } catch (const Json::exception&) {
    throw cannotWrite("glTF (the file written could not be read back)", target);
  }
  std::optional<int> material;
  for (const SceneComponent& component : scene.components) {
    const auto lines = linesOf(component.shape.shape);
    if (lines.empty()) continue;
    if (!material) material = lineMaterial(gltf);
    Json primitives = Json::array();
    for (const auto& line : lines)
      primitives.push_back(
          {{"attributes", {{"POSITION", appendPositions(gltf, line)}}}, {"mode", kLineStrip}, {"material", *material}});
    Json& node = nodeNamed(gltf, component.name);
    if (node.contains("mesh")) {  // faces too: the lines join their mesh
      for (Json& primitive : primitives)
        gltf.json["meshes"][node["mesh"].get<std::size_t>()]["primitives"].push_back(primitive);
    } else {
      gltf.json["meshes"].push_back({{"name", component.name}, {"primitives", primitives}});
      node["mesh"] = gltf.json["meshes"].size() - 1;
    }
  }
  Json& buffers = gltf.json["buffers"];
  if (buffers.empty()) buffers.push_back(Json::object());
  buffers[0]["byteLength"] = gltf.buffer.size();
  if (!binary) buffers[0]["uri"] = bufferPath(file, gltf.json).filename().string();
  if (binary) return writeGlb(file, std::move(gltf), target);
  writeGltfFiles(file, gltf, target);
}

}  // namespace airshape::exporting
