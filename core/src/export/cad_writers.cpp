// The exact (B-spline) formats: STEP (our writer where it can, docs/export.md), IGES through
// the XCAF document, which carries component and face names, and OCCT's own BREP.
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include "airshape/error.h"
#include "format_writers.h"
#include "step_brep_writer.h"
#include "xde_module.h"

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
  writeWithXcaf("step", scene, path, target);
}

void writeIges(const ExportScene& scene, const std::string& path, const std::string& target) {
  writeWithXcaf("iges", scene, path, target);
}

void writeBrep(const ExportScene& scene, const std::string& path, const std::string& target) {
  if (!BRepTools::Write(sceneCompound(scene), path.c_str())) throw cannotWrite("BREP", target);
}

}  // namespace airshape::exporting
