#pragma once

#include <TDocStd_Document.hxx>

#include "airshape/export/export_scene.h"

namespace airshape::exporting {

/// An XCAF document of a scene, for the OCCT writers that carry names: one assembly named
/// after the scene, one part per component named by its uID (its instance too), each
/// named face a named sub-shape of its part, each part on a layer of its own name.
/// The document is closed when the holder goes.
class SceneDocument {
 public:
  explicit SceneDocument(const ExportScene& scene);
  ~SceneDocument();
  SceneDocument(const SceneDocument&) = delete;
  SceneDocument& operator=(const SceneDocument&) = delete;

  const Handle(TDocStd_Document) & document() const { return document_; }

 private:
  Handle(TDocStd_Document) document_;
};

}  // namespace airshape::exporting
