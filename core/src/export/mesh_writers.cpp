// The triangulated formats: binary STL, glTF/GLB and OBJ (OCCT's writers; glTF and OBJ
// through the XCAF document, one node per component, in xde_writers.cpp; their lines are
// added by gltf_lines.cpp and obj_lines.cpp). VTK PolyData is vtp_writer.cpp.
#include <StlAPI_Writer.hxx>

#include "airshape/error.h"
#include "format_writers.h"
#include "gltf_lines.h"
#include "mesh_lines.h"
#include "obj_lines.h"
#include "xde_module.h"

namespace airshape::exporting {

void writeStl(const ExportScene& scene, const std::string& path, const std::string& target) {
  StlAPI_Writer writer;
  writer.ASCIIMode() = false;
  if (!writer.Write(sceneCompound(scene), path.c_str())) throw cannotWrite("STL", target);
}

void writeGltf(const ExportScene& scene, const std::string& path, const std::string& target, bool binary) {
  // OCCT's writer takes the triangles of faces, and writes nothing for a scene of lines
  // alone; the lines follow.
  if (hasFaces(scene)) writeWithXcaf(binary ? "glb" : "gltf", scene, path, target);
  addLinesToGltf(scene, path, target, binary);
}

void writeObj(const ExportScene& scene, const std::string& path, const std::string& target) {
  if (hasFaces(scene)) writeWithXcaf("obj", scene, path, target);
  addLinesToObj(scene, path, target);
}

}  // namespace airshape::exporting
