#pragma once

#include <string>

#include "airshape/export/export_options.h"
#include "airshape/export/export_scene.h"

namespace airshape::exporting {

/// What the browser viewer (docs/viewer.md) shows of each component of a scene besides its
/// triangles, as a JSON array: name, type, volume [m³], area [m²], box (CPACS axes), the
/// names of its faces in the order of the glTF primitives, and its B-rep edges (section
/// profiles, guide curves, borders) as polylines in glTF's axes. The scene must be
/// triangulated.
std::string viewerComponentsJson(const ExportScene& scene);

/// The scene as GLB bytes (glTF 2.0, y up, one node per component), triangulated as
/// `options` say. Throws Error(WriteFailed) when it cannot be written.
std::string sceneGlb(const ExportScene& scene, const ExportOptions& options);

}  // namespace airshape::exporting
