// The triangulated formats: binary STL, glTF/GLB and OBJ (OCCT's writers; glTF and OBJ
// through the XCAF document, one node per component, in xde_writers.cpp). VTK PolyData is
// vtp_writer.cpp.
#include <StlAPI_Writer.hxx>

#include "airshape/error.h"
#include "format_writers.h"
#include "xde_module.h"

namespace airshape::exporting {

void writeStl(const ExportScene& scene, const std::string& path, const std::string& target) {
  StlAPI_Writer writer;
  writer.ASCIIMode() = false;
  if (!writer.Write(sceneCompound(scene), path.c_str())) throw cannotWrite("STL", target);
}

void writeGltf(const ExportScene& scene, const std::string& path, const std::string& target, bool binary) {
  writeWithXcaf(binary ? "glb" : "gltf", scene, path, target);
}

void writeObj(const ExportScene& scene, const std::string& path, const std::string& target) {
  writeWithXcaf("obj", scene, path, target);
}

}  // namespace airshape::exporting
