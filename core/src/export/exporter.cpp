#include "airshape/export/exporter.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <map>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Standard_Failure.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/output_file.h"
#include "airshape/viewer/page.h"
#include "format_writers.h"
#include "mesh_lines.h"
#include "scene_mesh.h"

namespace airshape::exporting {

namespace {

const std::map<std::string, Format>& formatsByExtension() {
  static const std::map<std::string, Format> formats = {
      {".step", Format::Step}, {".stp", Format::Step}, {".iges", Format::Iges}, {".igs", Format::Iges},
      {".brep", Format::Brep}, {".stl", Format::Stl},  {".vtp", Format::Vtp},   {".gltf", Format::Gltf},
      {".glb", Format::Glb},   {".obj", Format::Obj},  {".html", Format::Html}, {".htm", Format::Html}};
  return formats;
}

/// OCCT's writers report transfer statistics on stdout, which would mix with a program's
/// own output; only their failures are let through.
void quietenKernelMessages() {
  static const bool quiet = [] {
    for (const Handle(Message_Printer) & printer : Message::DefaultMessenger()->Printers())
      printer->SetTraceLevel(Message_Fail);
    return true;
  }();
  (void)quiet;
}

bool isTriangulated(Format format) {
  return format != Format::Step && format != Format::Iges && format != Format::Brep;
}

/// STL holds triangles only; VTK PolyData, glTF (the viewer page's too) and OBJ hold lines as
/// polylines, the CAD formats as curves.
bool holdsLines(Format format) { return format != Format::Stl; }

void writeFormat(const ExportScene& scene, const std::string& path, Format format, const std::string& target) {
  switch (format) {
    case Format::Step:
      return writeStep(scene, path, target);
    case Format::Iges:
      return writeIges(scene, path, target);
    case Format::Brep:
      return writeBrep(scene, path, target);
    case Format::Stl:
      return writeStl(scene, path, target);
    case Format::Vtp:
      return writeVtp(scene, path, target);
    case Format::Gltf:
      return writeGltf(scene, path, target, false);
    case Format::Glb:
      return writeGltf(scene, path, target, true);
    case Format::Obj:
      return writeObj(scene, path, target);
    case Format::Html:
      return writeHtml(scene, path, target);
  }
}

}  // namespace

Format formatOfPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const auto format = formatsByExtension().find(extension);
  if (format == formatsByExtension().end())
    throw Error(ErrorCode::InvalidArgument,
                "unknown export format '" + extension + "' (known: " + knownExtensions() + ")", path);
  if (format->second == Format::Html && !viewer::available())
    throw Error(ErrorCode::NotImplemented, viewer::kUnavailable, path);
  return format->second;
}

std::string formatName(Format format) {
  switch (format) {
    case Format::Step:
      return "STEP";
    case Format::Iges:
      return "IGES";
    case Format::Brep:
      return "BREP";
    case Format::Stl:
      return "STL";
    case Format::Vtp:
      return "VTK PolyData";
    case Format::Gltf:
      return "glTF";
    case Format::Glb:
      return "GLB";
    case Format::Obj:
      return "OBJ";
    case Format::Html:
      return "HTML viewer page";
  }
  return "?";
}

std::string knownExtensions() {
  std::string list;
  for (const auto& [extension, format] : formatsByExtension()) list += (list.empty() ? "" : " ") + extension;
  return list;
}

std::vector<std::string> componentsLeftOutOf(const ExportScene& scene, Format format) {
  std::vector<std::string> leftOut;
  if (holdsLines(format)) return leftOut;
  for (const SceneComponent& component : scene.components)
    if (!hasFaces(component.shape.shape)) leftOut.push_back(component.name);
  return leftOut;
}

void writeScene(const ExportScene& scene, const std::string& path, Format format, const ExportOptions& options) {
  if (!scene.components.empty() && componentsLeftOutOf(scene, format).size() == scene.components.size())
    throw Error(ErrorCode::InvalidArgument,
                formatName(format) + " holds triangles only, and every component to write is lines (stiffeners, " +
                    "beams): write .vtp, .glb, .gltf, .obj, .step, .iges or .brep, or sweep their "
                    "profiles with --profiles",
                path);
  quietenKernelMessages();
  if (isTriangulated(format)) triangulate(scene, options);
  writeFileSafely(path, [&](const std::string& temporaryPath) {
    try {
      writeFormat(scene, temporaryPath, format, path);
    } catch (const Standard_Failure& failure) {
      throw Error(ErrorCode::WriteFailed,
                  "cannot write " + formatName(format) + ": geometry kernel failure: " + failure.GetMessageString(),
                  path);
    }
  });
}

void exportConfiguration(const Configuration& configuration, const std::string& path, const ExportOptions& options) {
  const Format format = formatOfPath(path);
  const auto start = std::chrono::steady_clock::now();
  const ExportScene scene = buildScene(configuration, options);
  if (scene.components.empty())
    throw Error(ErrorCode::NotImplemented, "nothing to export: no plugin builds any component of the configuration",
                configuration.source());
  if (options.progress)
    options.progress({0, 0, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                      "writing " + formatName(format)});
  writeScene(scene, path, format, options);
}

}  // namespace airshape::exporting
