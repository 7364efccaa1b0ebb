// The triangulated formats: binary STL, glTF/GLB and OBJ (OCCT's writers; glTF and OBJ
// through the XCAF document, one node per component). VTK PolyData is vtp_writer.cpp.
#include <Message_ProgressRange.hxx>
#include <RWGltf_CafWriter.hxx>
#include <RWMesh_CoordinateSystem.hxx>
#include <RWObj_CafWriter.hxx>
#include <StlAPI_Writer.hxx>
#include <TColStd_IndexedDataMapOfStringString.hxx>

#include "airshape/error.h"
#include "format_writers.h"
#include "scene_document.h"

namespace airshape::exporting {

namespace {

TColStd_IndexedDataMapOfStringString fileInfo() {
  TColStd_IndexedDataMapOfStringString info;
  info.Add("generator", "airshape");
  return info;
}

}  // namespace

void writeStl(const ExportScene& scene, const std::string& path, const std::string& target) {
  StlAPI_Writer writer;
  writer.ASCIIMode() = false;
  if (!writer.Write(sceneCompound(scene), path.c_str())) throw cannotWrite("STL", target);
}

void writeGltf(const ExportScene& scene, const std::string& path, const std::string& target, bool binary) {
  const SceneDocument document(scene);
  RWGltf_CafWriter writer(path.c_str(), binary);
  // CPACS is z-up in metres; glTF is y-up in metres.
  writer.ChangeCoordinateSystemConverter().SetInputLengthUnit(1.0);
  writer.ChangeCoordinateSystemConverter().SetInputCoordinateSystem(RWMesh_CoordinateSystem_Zup);
  if (!writer.Perform(document.document(), fileInfo(), Message_ProgressRange()))
    throw cannotWrite(binary ? "GLB" : "glTF", target);
}

void writeObj(const ExportScene& scene, const std::string& path, const std::string& target) {
  const SceneDocument document(scene);
  RWObj_CafWriter writer(path.c_str());
  if (!writer.Perform(document.document(), fileInfo(), Message_ProgressRange())) throw cannotWrite("OBJ", target);
}

}  // namespace airshape::exporting
