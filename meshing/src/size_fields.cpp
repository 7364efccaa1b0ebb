#include "size_fields.h"

#include <algorithm>
#include <set>

#include <gmsh.h>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "airshape/error.h"
#include "gmsh_session.h"

namespace airshape::meshing {

namespace {

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

bool isBoundary(const FaceLabel& label) { return label.component == "farfield" || label.component == "symmetry"; }

/// The segment a face name belongs to ("W1_Seg1" of "W1_Seg1/upper") and its side.
std::pair<std::string, std::string> segmentAndSide(const std::string& face) {
  const std::size_t slash = face.rfind('/');
  return slash == std::string::npos ? std::make_pair(face, std::string())
                                    : std::make_pair(face.substr(0, slash), face.substr(slash + 1));
}

/// Whether an edge between two faces is a trailing edge: it bounds a blunt trailing edge's
/// face, or it is where a segment's upper and lower skins meet.
bool isTrailingEdge(const FaceLabel& a, const FaceLabel& b) {
  if (endsWith(a.face, "/trailingEdge") || endsWith(b.face, "/trailingEdge")) return true;
  const auto [segmentA, sideA] = segmentAndSide(a.face);
  const auto [segmentB, sideB] = segmentAndSide(b.face);
  return segmentA == segmentB && ((sideA == "upper" && sideB == "lower") || (sideA == "lower" && sideB == "upper"));
}

/// The Gmsh tags of the curves to refine: trailing edges and the curves where two
/// components of the aircraft meet.
std::vector<double> curvesToRefine(const TopoDS_Shape& shape, const std::vector<FaceLabel>& labels,
                                   const ImportedShape& imported) {
  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
  std::vector<double> curves;
  for (int index = 1; index <= edges.Extent(); ++index) {
    const TopTools_ListOfShape* around = facesOfEdge.Seek(edges(index));
    if (around == nullptr || around->Extent() < 2) continue;
    const FaceLabel& a = labels[static_cast<std::size_t>(faces.FindIndex(around->First()) - 1)];
    const FaceLabel& b = labels[static_cast<std::size_t>(faces.FindIndex(around->Last()) - 1)];
    if (isBoundary(a) || isBoundary(b)) continue;
    if (a.component != b.component || isTrailingEdge(a, b))
      curves.push_back(imported.curves[static_cast<std::size_t>(index - 1)]);
  }
  return curves;
}

/// The same size everywhere: a Box field whose box holds everything (Gmsh's MathEval field
/// parses its formula at every point it is asked, which made surface meshes ten times slower).
int constantSize(double value) {
  const int field = gmsh::model::mesh::field::add("Box");
  for (const char* name : {"VIn", "VOut"}) gmsh::model::mesh::field::setNumber(field, name, value);
  for (const char* name : {"XMin", "YMin", "ZMin"}) gmsh::model::mesh::field::setNumber(field, name, -1e30);
  for (const char* name : {"XMax", "YMax", "ZMax"}) gmsh::model::mesh::field::setNumber(field, name, 1e30);
  return field;
}

/// Size `size` near the given entities, growing to `far` over `reach`.
/// `sampling`: points per curve (per side of a surface) the distance is measured to.
int sizeNear(const std::string& list, const std::vector<double>& tags, double size, double near, double far,
             double reach, int sampling) {
  const int distance = gmsh::model::mesh::field::add("Distance");
  gmsh::model::mesh::field::setNumbers(distance, list, tags);
  gmsh::model::mesh::field::setNumber(distance, "NNodesByEdge", sampling);
  const int threshold = gmsh::model::mesh::field::add("Threshold");
  gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
  gmsh::model::mesh::field::setNumber(threshold, "LcMin", size);
  gmsh::model::mesh::field::setNumber(threshold, "LcMax", far);
  gmsh::model::mesh::field::setNumber(threshold, "DistMin", near);
  gmsh::model::mesh::field::setNumber(threshold, "DistMax", reach);
  gmsh::model::mesh::field::setNumber(threshold, "StopAtDistMax", 1);  // beyond `reach` the others decide
  return threshold;
}

/// `size` on the surfaces of one component and their curves.
int sizeOnComponent(const std::string& uid, double size, const TopoDS_Shape& shape,
                    const std::vector<FaceLabel>& labels, const ImportedShape& imported) {
  std::vector<double> surfaces;
  std::set<int> curves;
  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  for (std::size_t index = 0; index < labels.size(); ++index) {
    if (labels[index].component != uid) continue;
    surfaces.push_back(imported.surfaces[index]);
    TopTools_IndexedMapOfShape bounding;
    TopExp::MapShapes(faces(static_cast<int>(index + 1)), TopAbs_EDGE, bounding);
    for (int edge = 1; edge <= bounding.Extent(); ++edge)
      curves.insert(imported.curves[static_cast<std::size_t>(edges.FindIndex(bounding(edge)) - 1)]);
  }
  if (surfaces.empty())
    throw Error(ErrorCode::InvalidArgument, "--size: no surface of the mesh belongs to '" + uid + "'");
  const int restrict = gmsh::model::mesh::field::add("Restrict");
  gmsh::model::mesh::field::setNumber(restrict, "InField", constantSize(size));
  gmsh::model::mesh::field::setNumbers(restrict, "FacesList", surfaces);
  gmsh::model::mesh::field::setNumbers(restrict, "EdgesList", std::vector<double>(curves.begin(), curves.end()));
  return restrict;
}

std::vector<double> aircraftSurfaces(const std::vector<FaceLabel>& labels, const ImportedShape& imported) {
  std::vector<double> surfaces;
  for (std::size_t index = 0; index < labels.size(); ++index)
    if (!isBoundary(labels[index])) surfaces.push_back(imported.surfaces[index]);
  return surfaces;
}

/// How fast the fluid's elements grow with the distance from the aircraft: size per metre.
constexpr double kGrowth = 0.2;

/// The fluid's size: the surface size at the given entities, growing to the far-field size.
int fluidGrowth(const std::string& list, const std::vector<double>& tags, const Sizes& sizes) {
  return sizeNear(list, tags, sizes.surface, 0, sizes.farfield, sizes.reach, 12);
}

}  // namespace

Sizes sizesFor(const MeshOptions& options, double length, double farfieldDistance) {
  Sizes sizes;
  sizes.surface = options.size > 0 ? options.size : length / 50;
  sizes.minimum = options.minSize > 0 ? options.minSize : sizes.surface / 50;
  if (sizes.minimum > sizes.surface)
    throw Error(ErrorCode::InvalidArgument, "--min-size " + std::to_string(sizes.minimum) +
                                                " exceeds the largest size " + std::to_string(sizes.surface));
  sizes.refined = std::max(sizes.minimum, sizes.surface / 8);
  sizes.farfield = std::max(sizes.surface, farfieldDistance / 8);
  sizes.reach = (sizes.farfield - sizes.surface) / kGrowth;
  return sizes;
}

void setSizeFields(const TopoDS_Shape& shape, const std::vector<FaceLabel>& labels, const ImportedShape& imported,
                   const MeshOptions& options, const Sizes& sizes) {
  callGmsh("setting the element sizes", [&] {
    const bool fluid = options.farfield.has_value();
    gmsh::option::setNumber("Mesh.MeshSizeMin", sizes.minimum);
    gmsh::option::setNumber("Mesh.MeshSizeMax", fluid ? sizes.farfield : sizes.surface);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", options.elementsPerCircle);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    // The fluid's sizes come from the distance to the aircraft alone: extended from the surface
    // meshes they would fill the space around the aircraft with its finest elements (millions).
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    std::vector<double> fields;
    if (const std::vector<double> curves = curvesToRefine(shape, labels, imported); !curves.empty())
      fields.push_back(
          sizeNear("EdgesList", curves, sizes.refined, sizes.refined, sizes.surface, 4 * sizes.surface, 12));
    for (const auto& [uid, size] : options.componentSizes)
      fields.push_back(sizeOnComponent(uid, size, shape, labels, imported));
    if (fluid) fields.push_back(fluidGrowth("FacesList", aircraftSurfaces(labels, imported), sizes));
    if (fields.empty()) return;  // the largest size and the curvature decide
    const int minimum = gmsh::model::mesh::field::add("Min");
    gmsh::model::mesh::field::setNumbers(minimum, "FieldsList", fields);
    gmsh::model::mesh::field::setAsBackgroundMesh(minimum);
  });
}

void setFluidSizes(const std::string& list, const std::vector<double>& tags, const Sizes& sizes) {
  callGmsh("setting the fluid's element sizes", [&] {
    gmsh::option::setNumber("Mesh.MeshSizeMin", sizes.minimum);
    gmsh::option::setNumber("Mesh.MeshSizeMax", sizes.farfield);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::model::mesh::field::setAsBackgroundMesh(fluidGrowth(list, tags, sizes));
  });
}

}  // namespace airshape::meshing
