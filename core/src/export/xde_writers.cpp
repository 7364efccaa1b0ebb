// The writers that go through OCCT's XCAF document (STEP and IGES with names and levels, glTF
// and OBJ with one node per component), in a module of their own: the XCAF toolkits bring
// OCCT's visualisation and image libraries with them, which take tens of milliseconds to load
// (docs/performance.md), so an export loads them only when it writes one of these.
#include <string>

#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <Message_ProgressRange.hxx>
#include <RWGltf_CafWriter.hxx>
#include <RWMesh_CoordinateSystem.hxx>
#include <RWObj_CafWriter.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TColStd_IndexedDataMapOfStringString.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <boost/config.hpp>

#include "format_writers.h"
#include "scene_document.h"

namespace airshape::exporting {

namespace {

TColStd_IndexedDataMapOfStringString fileInfo() {
  TColStd_IndexedDataMapOfStringString info;
  info.Add("generator", "airshape");
  return info;
}

void writeStepByXcaf(const ExportScene& scene, const std::string& path, const std::string& target) {
  const SceneDocument document(scene);
  STEPCAFControl_Writer writer;  // initialises the STEP parameters, so they are set after it
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.unit", "M");
  Interface_Static::SetIVal("write.stepcaf.subshapes.name", 1);
  writer.SetNameMode(true);
  writer.SetLayerMode(true);
  if (!writer.Transfer(document.document(), STEPControl_AsIs)) throw cannotWrite("STEP (transfer failed)", target);
  if (writer.Write(path.c_str()) != IFSelect_RetDone) throw cannotWrite("STEP", target);
}

void writeIgesByXcaf(const ExportScene& scene, const std::string& path, const std::string& target) {
  const SceneDocument document(scene);
  // The IGES writer scales from the document's length unit to the unit the file declares and
  // takes millimetres when the document names none, which wrote our metres 1000 times too
  // small. (OCCT 7.6's STEP writer does not scale by it; it keeps its default.)
  XCAFDoc_DocumentTool::SetLengthUnit(document.document(), 1.0, UnitsMethods_LengthUnit_Meter);
  IGESControl_Controller::Init();
  Interface_Static::SetCVal("write.iges.unit", "M");
  Interface_Static::SetIVal("write.iges.brep.mode", 1);  // solids as IGES 186 manifold solids
  IGESCAFControl_Writer writer;
  writer.SetNameMode(true);
  writer.SetLayerMode(true);
  if (!writer.Transfer(document.document())) throw cannotWrite("IGES (transfer failed)", target);
  if (!writer.Write(path.c_str())) throw cannotWrite("IGES", target);
}

void writeGltfByXcaf(const ExportScene& scene, const std::string& path, const std::string& target, bool binary) {
  const SceneDocument document(scene);
  RWGltf_CafWriter writer(path.c_str(), binary);
  // CPACS is z-up in metres; glTF is y-up in metres.
  writer.ChangeCoordinateSystemConverter().SetInputLengthUnit(1.0);
  writer.ChangeCoordinateSystemConverter().SetInputCoordinateSystem(RWMesh_CoordinateSystem_Zup);
  if (!writer.Perform(document.document(), fileInfo(), Message_ProgressRange()))
    throw cannotWrite(binary ? "GLB" : "glTF", target);
}

void writeObjByXcaf(const ExportScene& scene, const std::string& path, const std::string& target) {
  const SceneDocument document(scene);
  RWObj_CafWriter writer(path.c_str());
  if (!writer.Perform(document.document(), fileInfo(), Message_ProgressRange())) throw cannotWrite("OBJ", target);
}

}  // namespace

}  // namespace airshape::exporting

/// The module's one entry (xde_module.cpp loads it): writes `scene` in `format` (step, iges,
/// gltf, glb or obj) to `path`; throws Error naming `target`.
extern "C" BOOST_SYMBOL_EXPORT void airshape_write_with_xcaf(const std::string& format,
                                                             const airshape::exporting::ExportScene& scene,
                                                             const std::string& path, const std::string& target) {
  using namespace airshape::exporting;
  if (format == "step") return writeStepByXcaf(scene, path, target);
  if (format == "iges") return writeIgesByXcaf(scene, path, target);
  if (format == "gltf" || format == "glb") return writeGltfByXcaf(scene, path, target, format == "glb");
  if (format == "obj") return writeObjByXcaf(scene, path, target);
  throw airshape::Error(airshape::ErrorCode::InvalidArgument, "the XCAF writers know no format '" + format + "'");
}
