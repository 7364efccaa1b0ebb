#include "scene_document.h"

#include <TCollection_ExtendedString.hxx>
#include <TDataStd_Name.hxx>
#include <TopLoc_Location.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_LayerTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

namespace airshape::exporting {

namespace {

TCollection_ExtendedString extended(const std::string& text) { return TCollection_ExtendedString(text.c_str(), true); }

}  // namespace

SceneDocument::SceneDocument(const ExportScene& scene) {
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document_);
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(document_->Main());
  const Handle(XCAFDoc_LayerTool) layers = XCAFDoc_DocumentTool::LayerTool(document_->Main());
  const TDF_Label assembly = shapes->NewShape();
  TDataStd_Name::Set(assembly, extended(scene.name));
  for (const SceneComponent& component : scene.components) {
    const TDF_Label part = shapes->AddShape(component.shape.shape, false);
    TDataStd_Name::Set(part, extended(component.name));
    layers->SetLayer(part, extended(component.name));
    for (const auto& [name, face] : component.shape.faces) {
      const TDF_Label faceLabel = shapes->AddSubShape(part, face);
      if (!faceLabel.IsNull()) TDataStd_Name::Set(faceLabel, extended(name));
    }
    TDataStd_Name::Set(shapes->AddComponent(assembly, part, TopLoc_Location()), extended(component.name));
  }
  shapes->UpdateAssemblies();
}

SceneDocument::~SceneDocument() { XCAFApp_Application::GetApplication()->Close(document_); }

}  // namespace airshape::exporting
