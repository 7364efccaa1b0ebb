// VTK XML PolyData (.vtp): every triangle of every face and every line outside the faces (a
// stiffener's, as a polyline), with two per-cell string arrays, "component" (the
// uID) and "face" (the face's name; "line" for a line), so that a post-processor can pick out
// a component or one side of it.
#include <fstream>
#include <sstream>

#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "format_writers.h"
#include "mesh_lines.h"

namespace airshape::exporting {

namespace {

/// Cells of one kind (VTK's lines or polygons) with their per-cell names.
struct Cells {
  std::ostringstream connectivity, offsets;
  std::vector<const std::string*> componentOfCell, faceOfCell;
  std::size_t connected = 0;  ///< entries in connectivity so far

  void add(const std::vector<std::size_t>& points, const std::string& component, const std::string& face) {
    for (std::size_t point : points) connectivity << point << ' ';
    connectivity << '\n';
    connected += points.size();
    offsets << connected << '\n';
    componentOfCell.push_back(&component);
    faceOfCell.push_back(&face);
  }
};

/// Points, lines and triangles, as VTK wants them laid out.
struct PolyData {
  std::ostringstream points;
  std::size_t pointCount = 0;
  Cells lines, polygons;

  std::size_t addPoint(const gp_Pnt& p) {
    points << p.X() << ' ' << p.Y() << ' ' << p.Z() << '\n';
    return pointCount++;
  }
};

const std::string kLineName = "line";

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
  for (int i = 1; i <= mesh->NbNodes(); ++i) data.addPoint(mesh->Node(i).Transformed(placement));
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  for (int i = 1; i <= mesh->NbTriangles(); ++i) {
    int a, b, c;
    mesh->Triangle(i).Get(a, b, c);
    if (reversed) std::swap(b, c);
    data.polygons.add({first + a - 1, first + b - 1, first + c - 1}, component, faceName);
  }
}

/// A component's lines (edges outside faces), each one polyline.
void addLines(const TopoDS_Shape& shape, const std::string& component, PolyData& data) {
  for (const std::vector<gp_Pnt>& line : polylinesOf(shape)) {
    std::vector<std::size_t> points;
    for (const gp_Pnt& p : line) points.push_back(data.addPoint(p));
    data.lines.add(points, component, kLineName);
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

/// Lines before polygons in the cell arrays, as VTK numbers the cells.
std::vector<const std::string*> inCellOrder(const std::vector<const std::string*>& lines,
                                            const std::vector<const std::string*>& polygons) {
  std::vector<const std::string*> all(lines);
  all.insert(all.end(), polygons.begin(), polygons.end());
  return all;
}

void writeCells(std::ostream& out, const char* element, const Cells& cells) {
  out << "      <" << element << ">\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n"
      << cells.connectivity.str()
      << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"
      << cells.offsets.str() << "        </DataArray>\n      </" << element << ">\n";
}

void writeDocument(std::ostream& out, const PolyData& data) {
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << data.pointCount << "\" NumberOfVerts=\"0\" NumberOfLines=\""
      << data.lines.componentOfCell.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\""
      << data.polygons.componentOfCell.size() << "\">\n      <CellData>\n";
  writeStringArray(out, "component", inCellOrder(data.lines.componentOfCell, data.polygons.componentOfCell));
  writeStringArray(out, "face", inCellOrder(data.lines.faceOfCell, data.polygons.faceOfCell));
  out << "      </CellData>\n      <Points>\n"
         "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      << data.points.str() << "        </DataArray>\n      </Points>\n";
  writeCells(out, "Lines", data.lines);
  writeCells(out, "Polys", data.polygons);
  out << "    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

}  // namespace

void writeVtp(const ExportScene& scene, const std::string& path, const std::string& target) {
  PolyData data;
  data.points.precision(17);
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
    addLines(component.shape.shape, component.name, data);
  }
  std::ofstream out(path, std::ios::binary);
  writeDocument(out, data);
  out.close();
  if (!out) throw cannotWrite("VTK PolyData", target);
}

}  // namespace airshape::exporting
