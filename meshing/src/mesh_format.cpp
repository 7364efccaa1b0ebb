#include "airshape/meshing/mesh_format.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "airshape/error.h"

namespace airshape::meshing {

MeshFormat meshFormatOfPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".msh") return MeshFormat::Msh;
  if (extension == ".su2") return MeshFormat::Su2;
  if (extension == ".vtu") return MeshFormat::Vtu;
  if (extension == ".inp") return MeshFormat::Inp;
  if (extension == ".stl") return MeshFormat::Stl;
  if (extension == ".cgns")
    throw Error(ErrorCode::InvalidArgument,
                "CGNS: this build's Gmsh (Debian's) is built without CGNS; write .msh or .su2 instead", path);
  throw Error(ErrorCode::InvalidArgument, "unknown mesh format '" + extension + "' (known: .msh .su2 .vtu .inp .stl)",
              path);
}

std::string meshFormatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::Msh:
      return "Gmsh MSH 4.1";
    case MeshFormat::Su2:
      return "SU2";
    case MeshFormat::Vtu:
      return "VTK unstructured grid";
    case MeshFormat::Inp:
      return "Abaqus/CalculiX input";
    case MeshFormat::Stl:
      return "STL";
  }
  return "?";
}

}  // namespace airshape::meshing
