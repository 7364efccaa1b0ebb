#include "airshape/geometry/ruled_sections.h"

#include "airshape/plugin/core_module.h"

namespace airshape::geometry {

namespace {

/// The module, loaded on first use and never unloaded: shapes built through it hold OCCT types
/// of the toolkits it brought along, and such shapes (cached by configurations) may be destroyed
/// after every static, when an unloaded toolkit's code would be gone.
const boost::dll::shared_library& rulingModule() {
  static const auto* module = new boost::dll::shared_library(
      plugin::loadCoreModule("libairshape_ruled_sections.so", "the ruled loft through sections"));
  return *module;
}

}  // namespace

RuledSections ruledThroughSections(const std::vector<TopoDS_Wire>& wires) {
  using Entry = void(const std::vector<TopoDS_Wire>&, TopoDS_Shape&, TopoDS_Shape&, TopoDS_Shape&);
  RuledSections loft;
  rulingModule().get<Entry>("airshape_ruled_sections")(wires, loft.solid, loft.firstCap, loft.lastCap);
  return loft;
}

TopoDS_Face ruledFaceBetween(const TopoDS_Edge& first, const TopoDS_Edge& second) {
  using Entry = void(const TopoDS_Edge&, const TopoDS_Edge&, TopoDS_Face&);
  TopoDS_Face face;
  rulingModule().get<Entry>("airshape_ruled_face")(first, second, face);
  return face;
}

}  // namespace airshape::geometry
