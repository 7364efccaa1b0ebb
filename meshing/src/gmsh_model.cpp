#include "gmsh_model.h"

#include <algorithm>
#include <map>

#include <gmsh.h>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "gmsh_session.h"

namespace airshape::meshing {

namespace {

std::vector<int> sortedTags(int dimension) {
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dimension);
  std::vector<int> tags;
  for (const auto& [dim, tag] : entities) tags.push_back(tag);
  std::sort(tags.begin(), tags.end());
  return tags;
}

/// Whether Gmsh's surface `tag` is the face: the same point at the middle of the face's
/// parameter range (Gmsh keeps OCCT's parametrisation).
bool sameSurface(const TopoDS_Face& face, int tag) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const double u = (u0 + u1) / 2, v = (v0 + v1) / 2;
  TopLoc_Location location;
  const gp_Pnt ours = BRep_Tool::Surface(face, location)->Value(u, v).Transformed(location.Transformation());
  std::vector<double> theirs;
  gmsh::model::getValue(2, tag, {u, v}, theirs);
  return theirs.size() == 3 &&
         ours.Distance(gp_Pnt(theirs[0], theirs[1], theirs[2])) <= 1e-9 * (1 + ours.XYZ().Modulus());
}

}  // namespace

ImportedShape importIntoGmsh(const TopoDS_Shape& shape) {
  ImportedShape imported;
  callGmsh("handing the shape to Gmsh", [&] {
    gmsh::vectorpair top;
    gmsh::model::occ::importShapesNativePointer(&shape, top, false);
    gmsh::model::occ::synchronize();
    imported.surfaces = sortedTags(2);
    imported.curves = sortedTags(1);
    imported.volumes = sortedTags(3);
  });
  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  bool sameOrder = imported.surfaces.size() == static_cast<std::size_t>(faces.Extent()) &&
                   imported.curves.size() == static_cast<std::size_t>(edges.Extent());
  for (int index = 1; sameOrder && index <= faces.Extent(); ++index)
    sameOrder = sameSurface(TopoDS::Face(faces(index)), imported.surfaces[static_cast<std::size_t>(index - 1)]);
  if (!sameOrder)
    throw Error(ErrorCode::InvalidModel, "Gmsh took the shape with other faces than it has (" +
                                             std::to_string(imported.surfaces.size()) + " surfaces for " +
                                             std::to_string(faces.Extent()) + " faces)");
  return imported;
}

std::vector<PhysicalGroup> physicalGroups(const std::vector<FaceLabel>& labels, const ImportedShape& imported,
                                          const GroupsOfFace& groupsOf, bool fluid) {
  std::vector<PhysicalGroup> groups;
  std::map<std::string, std::size_t> byName;
  for (std::size_t index = 0; index < labels.size(); ++index)
    for (const std::string& name : groupsOf(labels[index])) {
      const auto [at, added] = byName.emplace(name, groups.size());
      if (added) groups.push_back({2, name, {}});
      groups[at->second].entities.push_back(imported.surfaces[index]);
    }
  if (fluid && !imported.volumes.empty()) groups.push_back({3, "fluid", imported.volumes});
  return groups;
}

void addToGmsh(const std::vector<PhysicalGroup>& groups) {
  callGmsh("naming the mesh's groups", [&] {
    int tag = 0;
    for (const PhysicalGroup& group : groups) {
      gmsh::model::addPhysicalGroup(group.dimension, group.entities, ++tag);
      gmsh::model::setPhysicalName(group.dimension, tag, group.name);
    }
  });
}

}  // namespace airshape::meshing
