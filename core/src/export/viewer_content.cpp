#include "airshape/export/viewer_content.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <nlohmann/json.hpp>

#include "airshape/geometry/brep_measures.h"
#include "format_writers.h"
#include "scene_mesh.h"

namespace airshape::exporting {

namespace {

/// The names of a component's faces in the order of its glTF mesh's primitives: OCCT's glTF
/// writer writes one primitive per triangulated face, in the order a face explorer finds them.
nlohmann::json faceNamesInMeshOrder(const NamedShape& shape) {
  nlohmann::json names = nlohmann::json::array();
  for (TopExp_Explorer face(shape.shape, TopAbs_FACE); face.More(); face.Next()) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangles = BRep_Tool::Triangulation(TopoDS::Face(face.Current()), location);
    if (triangles.IsNull() || triangles->NbTriangles() < 1) continue;
    std::string name;
    for (const auto& [faceName, named] : shape.faces)
      if (named.IsSame(face.Current())) {
        name = faceName;
        break;
      }
    names.push_back(name);
  }
  return names;
}

}  // namespace

std::string viewerComponentsJson(const ExportScene& scene) {
  nlohmann::json list = nlohmann::json::array();
  for (const SceneComponent& component : scene.components) {
    nlohmann::json entry = {{"name", component.name},
                            {"type", component.type},
                            {"volume", geometry::enclosedVolume(component.shape.shape)},
                            {"area", geometry::areaOf(component.shape.shape)},
                            {"faces", faceNamesInMeshOrder(component.shape)}};
    Bnd_Box box;
    BRepBndLib::Add(component.shape.shape, box);
    if (!box.IsVoid()) {
      double xMin, yMin, zMin, xMax, yMax, zMax;
      box.Get(xMin, yMin, zMin, xMax, yMax, zMax);
      entry["box"] = {{"min", {xMin, yMin, zMin}}, {"max", {xMax, yMax, zMax}}};
    }
    list.push_back(entry);
  }
  return list.dump();
}

std::string glbBytes(const ExportScene& scene, const std::string& path, const std::string& target) {
  writeGltf(scene, path, target, true);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  in.close();
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  if (bytes.str().empty()) throw cannotWrite("GLB", target);
  return bytes.str();
}

std::string sceneGlb(const ExportScene& scene, const ExportOptions& options) {
  triangulate(scene, options);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("airshape-" + std::to_string(::getpid()) + "-scene.glb");
  return glbBytes(scene, path.string(), path.string());
}

}  // namespace airshape::exporting
