#include "face_orientation.h"

#include <map>

#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

namespace airshape::meshing {

namespace {

/// An element's first three corners' normal (length: twice the triangle's area) and centre.
std::pair<gp_Vec, gp_Pnt> normalAndCentre(const MeshTables& tables, const ElementBlock& block, std::size_t element) {
  const std::size_t* nodes = &block.nodes[element * static_cast<std::size_t>(block.nodesPerElement)];
  const gp_Pnt a = nodePoint(tables.coordinates, nodes[0]), b = nodePoint(tables.coordinates, nodes[1]),
               c = nodePoint(tables.coordinates, nodes[2]);
  return {gp_Vec(a, b).Crossed(gp_Vec(a, c)), gp_Pnt((a.XYZ() + b.XYZ() + c.XYZ()) / 3)};
}

/// Whether the face's normal (as oriented in the shape) at the point nearest `point` runs
/// along `normal`.
bool alongFaceNormal(const TopoDS_Face& face, const gp_Pnt& point, const gp_Vec& normal) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  GeomAPI_ProjectPointOnSurf projection(point, surface);
  if (projection.NbPoints() == 0) return true;  // cannot tell: leave it as Gmsh made it
  double u = 0, v = 0;
  projection.LowerDistanceParameters(u, v);
  GeomLProp_SLProps properties(surface, u, v, 1, 1e-9);
  if (!properties.IsNormalDefined()) return true;
  gp_Vec faceNormal(properties.Normal());
  if (face.Orientation() == TopAbs_REVERSED) faceNormal.Reverse();
  return faceNormal.Dot(normal) >= 0;
}

}  // namespace

void orientLikeFaces(MeshTables& tables, const TopoDS_Shape& shape, const ImportedShape& imported) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  std::map<int, int> faceOfSurface;  // Gmsh tag -> index in `faces`
  for (std::size_t index = 0; index < imported.surfaces.size(); ++index)
    faceOfSurface[imported.surfaces[index]] = static_cast<int>(index + 1);
  // Per surface entity: its largest element (the one whose normal is surest).
  std::map<std::size_t, std::tuple<double, std::size_t, std::size_t>> largest;  // entity -> (area, block, element)
  for (std::size_t block = 0; block < tables.blocks.size(); ++block) {
    if (tables.blocks[block].dimension != 2) continue;
    for (std::size_t element = 0; element < tables.blocks[block].entity.size(); ++element) {
      const double area = normalAndCentre(tables, tables.blocks[block], element).first.Magnitude();
      auto& best = largest[tables.blocks[block].entity[element]];
      if (area > std::get<0>(best)) best = {area, block, element};
    }
  }
  std::vector<bool> turn(tables.entities.size(), false);
  for (const auto& [entity, best] : largest) {
    const auto face = faceOfSurface.find(tables.entities[entity].tag);
    if (face == faceOfSurface.end()) continue;
    const auto [normal, centre] = normalAndCentre(tables, tables.blocks[std::get<1>(best)], std::get<2>(best));
    turn[entity] = !alongFaceNormal(TopoDS::Face(faces(face->second)), centre, normal);
  }
  for (ElementBlock& block : tables.blocks) {
    if (block.dimension != 2) continue;
    const std::vector<int>& order = reversedNodeOrder(block.gmshType);
    const std::size_t perElement = static_cast<std::size_t>(block.nodesPerElement);
    std::vector<std::size_t> turned(perElement);
    for (std::size_t element = 0; element < block.entity.size(); ++element) {
      if (!turn[block.entity[element]]) continue;
      for (std::size_t place = 0; place < perElement; ++place)
        turned[place] = block.nodes[element * perElement + static_cast<std::size_t>(order[place])];
      std::copy(turned.begin(), turned.end(), block.nodes.begin() + static_cast<long>(element * perElement));
    }
  }
}

}  // namespace airshape::meshing
