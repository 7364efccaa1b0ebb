#pragma once

#include <string>

namespace airshape::meshing {

/// The mesh formats `airshape mesh` writes, chosen by the output's extension.
enum class MeshFormat { Msh, Su2, Vtu, Inp, Stl };

/// The format of an output path by its extension (.msh, .su2, .vtu, .inp, .stl, any case).
/// Throws Error(InvalidArgument) for any other, saying why for .cgns (Debian's Gmsh is built
/// without CGNS).
MeshFormat meshFormatOfPath(const std::string& path);

/// "Gmsh MSH 4.1", "SU2", ... for messages.
std::string meshFormatName(MeshFormat format);

}  // namespace airshape::meshing
