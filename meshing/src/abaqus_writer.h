#pragma once

#include <string>

#include "mesh_tables.h"

namespace airshape::meshing {

/// Writes the mesh as an Abaqus / CalculiX input deck: *NODE, *ELEMENT blocks (shells S3, S4,
/// S6, S8; beams B31, B32; solids C3D4, C3D10), and per physical group an element set and a
/// node set named after it (characters other than letters, digits and _ written as _). The
/// deck holds the mesh only: materials, sections, steps are the analyst's.
void writeAbaqus(const MeshTables& mesh, const std::string& path);

/// The set name Abaqus and CalculiX take for a group name: letters, digits and _, starting with
/// a letter, at most 80 characters.
std::string abaqusSetName(const std::string& name);

}  // namespace airshape::meshing
