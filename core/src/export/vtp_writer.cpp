// VTK XML PolyData (.vtp): every triangle of every face, with two per-cell string arrays,
// "component" (the uID) and "face" (the face's name), so that a post-processor can pick
// out a component or a wing's upper side.
#include <fstream>
#include <sstream>

#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "format_writers.h"

namespace airshape::exporting {

namespace {

/// Triangles with their per-cell names, as VTK wants them laid out.
struct PolyData {
  std::ostringstream points, connectivity, offsets;
  std::vector<const std::string*> componentOfCell, faceOfCell;
  std::size_t pointCount = 0;
};

/// The name of each named face, found by the face itself (orientation aside).
std::vector<std::string> faceNames(const NamedShape& shape, TopTools_DataMapOfShapeInteger& indexOfFace) {
  std::vector<std::string> names{""};  // 0: a face without a name
  for (const auto& [name, face] : shape.faces) {
    names.push_back(name);
    indexOfFace.Bind(face, static_cast<int>(names.size() - 1));
  }
  return names;
}

void addFace(const TopoDS_Face& face, const std::string& component, const std::string& faceName, PolyData& data) {
  TopLoc_Location location;
  const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, location);
  if (mesh.IsNull()) return;
  const gp_Trsf placement = location.Transformation();
  const std::size_t first = data.pointCount;
  data.points.precision(17);
  for (int i = 1; i <= mesh->NbNodes(); ++i) {
    const gp_Pnt p = mesh->Node(i).Transformed(placement);
    data.points << p.X() << ' ' << p.Y() << ' ' << p.Z() << '\n';
  }
  data.pointCount += static_cast<std::size_t>(mesh->NbNodes());
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  for (int i = 1; i <= mesh->NbTriangles(); ++i) {
    int a, b, c;
    mesh->Triangle(i).Get(a, b, c);
    if (reversed) std::swap(b, c);
    data.connectivity << first + a - 1 << ' ' << first + b - 1 << ' ' << first + c - 1 << '\n';
    data.offsets << 3 * (data.componentOfCell.size() + 1) << '\n';
    data.componentOfCell.push_back(&component);
    data.faceOfCell.push_back(&faceName);
  }
}

/// A VTK string array in ASCII: each string as its character codes, ended by 0.
void writeStringArray(std::ostream& out, const char* name, const std::vector<const std::string*>& values) {
  out << "        <Array type=\"String\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (const std::string* value : values) {
    for (unsigned char character : *value) out << static_cast<int>(character) << ' ';
    out << "0\n";
  }
  out << "        </Array>\n";
}

void writeDocument(std::ostream& out, const PolyData& data) {
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << data.pointCount
      << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
      << data.componentOfCell.size() << "\">\n      <CellData>\n";
  writeStringArray(out, "component", data.componentOfCell);
  writeStringArray(out, "face", data.faceOfCell);
  out << "      </CellData>\n      <Points>\n"
         "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      << data.points.str()
      << "        </DataArray>\n      </Points>\n      <Polys>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n"
      << data.connectivity.str()
      << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"
      << data.offsets.str() << "        </DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

}  // namespace

void writeVtp(const ExportScene& scene, const std::string& path, const std::string& target) {
  PolyData data;
  std::vector<std::vector<std::string>> names;  // kept alive: the cells point into them
  names.reserve(scene.components.size());
  for (const SceneComponent& component : scene.components) {
    TopTools_DataMapOfShapeInteger indexOfFace;
    names.push_back(faceNames(component.shape, indexOfFace));
    for (TopExp_Explorer explorer(component.shape.shape, TopAbs_FACE); explorer.More(); explorer.Next()) {
      const TopoDS_Face& face = TopoDS::Face(explorer.Current());
      const int index = indexOfFace.IsBound(face) ? indexOfFace.Find(face) : 0;
      addFace(face, component.name, names.back()[static_cast<std::size_t>(index)], data);
    }
  }
  std::ofstream out(path, std::ios::binary);
  writeDocument(out, data);
  out.close();
  if (!out) throw cannotWrite("VTK PolyData", target);
}

}  // namespace airshape::exporting
