#include "airshape/export/viewer_content.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <nlohmann/json.hpp>

#include "airshape/geometry/brep_measures.h"
#include "airshape/query/box_answer.h"
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

/// The component's B-rep edges (section profiles, guide curves, segment and patch borders,
/// seams) as polylines in the page's axes (glTF's: y up, so CPACS (x, y, z) is (x, z, -y)),
/// each a flat list x0, y0, z0, x1, ...; sampled within a thousandth of the component's size.
nlohmann::json edgePolylines(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  nlohmann::json lines = nlohmann::json::array();
  if (box.IsVoid()) return lines;
  const double deflection = 1e-3 * std::sqrt(box.SquareExtent());
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    BRepAdaptor_Curve curve(edge);
    GCPnts_QuasiUniformDeflection samples(curve, deflection);
    if (!samples.IsDone() || samples.NbPoints() < 2) continue;
    nlohmann::json line = nlohmann::json::array();
    for (int k = 1; k <= samples.NbPoints(); ++k) {
      const gp_Pnt p = samples.Value(k);
      for (const double coordinate : {p.X(), p.Z(), -p.Y()}) line.push_back(static_cast<float>(coordinate));
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace

std::string viewerComponentsJson(const ExportScene& scene) {
  nlohmann::json list = nlohmann::json::array();
  for (const SceneComponent& component : scene.components) {
    nlohmann::json entry = {{"name", component.name},
                            {"type", component.type},
                            {"volume", geometry::enclosedVolume(component.shape.shape)},
                            {"area", geometry::areaOf(component.shape.shape)},
                            {"faces", faceNamesInMeshOrder(component.shape)},
                            {"edges", edgePolylines(component.shape.shape)}};
    // The tight box of the exact geometry, as the bounding_box op gives it.
    const Bnd_Box box = query::tightBox(component.shape.shape);
    if (!box.IsVoid()) entry["box"] = query::boxAnswer(box);
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
