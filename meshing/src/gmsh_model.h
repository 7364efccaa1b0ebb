#pragma once

#include <functional>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "labelled_shape.h"

namespace airshape::meshing {

/// A shape imported into Gmsh's model: the Gmsh tag of each of its faces (surfaces) and edges
/// (curves), in the order TopExp::MapShapes lists them, and its solids' tags (volumes).
struct ImportedShape {
  std::vector<int> surfaces;
  std::vector<int> curves;
  std::vector<int> volumes;
};

/// Hands a shape to Gmsh's OpenCASCADE kernel in memory (no file in between). Throws Error
/// when Gmsh does not take it or numbers its faces otherwise than the shape lists them.
ImportedShape importIntoGmsh(const TopoDS_Shape& shape);

/// A physical group: its name and the tags of its entities of one dimension.
struct PhysicalGroup {
  int dimension = 2;
  std::string name;
  std::vector<int> entities;
};

/// The names of the surface groups a labelled face belongs to.
using GroupsOfFace = std::function<std::vector<std::string>(const FaceLabel&)>;

/// The mesh's physical groups: the surface groups `groupsOf` puts each face in (in the order
/// they first occur), and the fluid volume "fluid" when the shape has volumes and `fluid` is set.
std::vector<PhysicalGroup> physicalGroups(const std::vector<FaceLabel>& labels, const ImportedShape& imported,
                                          const GroupsOfFace& groupsOf, bool fluid);

/// Adds the groups to Gmsh's model, numbered 1, 2, ... over every dimension: OpenFOAM's
/// gmshToFoam names a cell zone after a surface group that has the volume group's number.
void addToGmsh(const std::vector<PhysicalGroup>& groups);

}  // namespace airshape::meshing
