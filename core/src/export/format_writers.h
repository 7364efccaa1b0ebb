#pragma once

#include <string>

#include <TopoDS_Compound.hxx>

#include "airshape/error.h"
#include "airshape/export/export_scene.h"

// One writer per file format. Each writes a scene to `path` (a temporary name the caller
// moves into place) and throws Error(WriteFailed) naming `target`, the user's file name,
// when it cannot. The triangulated formats expect the scene triangulated (scene_mesh.h).

namespace airshape::exporting {

/// The error of a writer that failed, naming the user's file.
inline Error cannotWrite(const std::string& format, const std::string& target) {
  return Error(ErrorCode::WriteFailed, "cannot write " + format + " (disk full or not writable?)", target);
}

/// Every component solid of a scene in one compound, in scene order.
TopoDS_Compound sceneCompound(const ExportScene& scene);

void writeStep(const ExportScene& scene, const std::string& path, const std::string& target);
void writeIges(const ExportScene& scene, const std::string& path, const std::string& target);
void writeBrep(const ExportScene& scene, const std::string& path, const std::string& target);
void writeStl(const ExportScene& scene, const std::string& path, const std::string& target);
void writeVtp(const ExportScene& scene, const std::string& path, const std::string& target);
void writeGltf(const ExportScene& scene, const std::string& path, const std::string& target, bool binary);
void writeObj(const ExportScene& scene, const std::string& path, const std::string& target);
/// The bytes of the scene as GLB, written to `path` (a scratch file, removed again) because
/// OCCT's glTF writer writes files only.
std::string glbBytes(const ExportScene& scene, const std::string& path, const std::string& target);
/// A page that opens from disk in a browser (docs/viewer.md): the scene as GLB inlined in the
/// viewer, with each component's type and measures.
void writeHtml(const ExportScene& scene, const std::string& path, const std::string& target);

}  // namespace airshape::exporting
