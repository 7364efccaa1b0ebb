// The exact (B-spline) formats: STEP and IGES through the XCAF document, which carries
// component and face names, and OCCT's own BREP.
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFDoc_DocumentTool.hxx>

#include "airshape/error.h"
#include "format_writers.h"
#include "scene_document.h"
#include "step_brep_writer.h"

namespace airshape::exporting {

TopoDS_Compound sceneCompound(const ExportScene& scene) {
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  for (const SceneComponent& component : scene.components) builder.Add(compound, component.shape.shape);
  return compound;
}

void writeStep(const ExportScene& scene, const std::string& path, const std::string& target) {
  if (brepStepWritable(scene)) return writeBrepStep(scene, path, target);
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

void writeIges(const ExportScene& scene, const std::string& path, const std::string& target) {
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

void writeBrep(const ExportScene& scene, const std::string& path, const std::string& target) {
  if (!BRepTools::Write(sceneCompound(scene), path.c_str())) throw cannotWrite("BREP", target);
}

}  // namespace airshape::exporting
