// The HTML viewer page: the scene written as GLB, inlined in the viewer (viewer/) with what
// the page shows of each component besides its triangles.
#include <fstream>

#include "airshape/export/viewer_content.h"
#include "airshape/viewer/page.h"
#include "format_writers.h"

namespace airshape::exporting {

void writeHtml(const ExportScene& scene, const std::string& path, const std::string& target) {
  // The scene is triangulated already (exporter.cpp); the GLB's scratch file lies next to the page.
  const std::string glb = glbBytes(scene, path + ".glb", target);
  std::ofstream out(path, std::ios::binary);
  out << viewer::standalonePage({scene.name, viewerComponentsJson(scene)}, glb);
  if (!out.flush()) throw cannotWrite("HTML", target);
}

}  // namespace airshape::exporting
