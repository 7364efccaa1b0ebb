#pragma once

#include <string>
#include <vector>

#include "airshape/export/export_options.h"
#include "airshape/export/export_scene.h"

namespace airshape {
class Configuration;
}

namespace airshape::exporting {

/// The file formats an export writes, chosen by the output's extension.
enum class Format { Step, Iges, Brep, Stl, Vtp, Gltf, Glb, Obj, Html };

/// The format of an output path by its extension (.step/.stp, .iges/.igs, .brep, .stl,
/// .vtp, .gltf, .glb, .obj, .html/.htm, any case). Throws Error(InvalidArgument) for any
/// other, and for .html when this build has no viewer (docs/viewer.md).
Format formatOfPath(const std::string& path);
/// "STEP", "IGES", ... for messages.
std::string formatName(Format format);
/// The extensions formatOfPath knows, for help texts.
std::string knownExtensions();

/// The components of a scene that a format cannot hold: those made of lines alone (stiffeners
/// and beams without --profiles) in STL, which holds triangles only. VTK
/// PolyData, glTF (and so the viewer page), OBJ, STEP, IGES and BREP hold lines.
std::vector<std::string> componentsLeftOutOf(const ExportScene& scene, Format format);

/// Writes a scene to `path` in `format`, safely (complete or not at all, see
/// writeFileSafely); components the format cannot hold are left out (componentsLeftOutOf).
/// Throws Error(WriteFailed) naming the file when it cannot be written, and
/// Error(InvalidArgument) when the format can hold none of the components.
void writeScene(const ExportScene& scene, const std::string& path, Format format, const ExportOptions& options);

/// Builds the scene of a configuration and writes it to `path` in the format its
/// extension names.
void exportConfiguration(const Configuration& configuration, const std::string& path, const ExportOptions& options);

}  // namespace airshape::exporting
