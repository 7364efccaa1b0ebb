#include "airshape/geometry/ruled_sections.h"

#include "airshape/plugin/core_module.h"

namespace airshape::geometry {

RuledSections ruledThroughSections(const std::vector<TopoDS_Wire>& wires) {
  using Entry = void(const std::vector<TopoDS_Wire>&, TopoDS_Shape&, TopoDS_Shape&, TopoDS_Shape&);
  static const boost::dll::shared_library module =
      plugin::loadCoreModule("libairshape_ruled_sections.so", "the ruled loft through sections");
  RuledSections loft;
  module.get<Entry>("airshape_ruled_sections")(wires, loft.solid, loft.firstCap, loft.lastCap);
  return loft;
}

}  // namespace airshape::geometry
