#pragma once

#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

namespace airshape::geometry {

/// The solid of OCCT's ruled loft through closed wires (BRepOffsetAPI_ThruSections, ruled):
/// between each two consecutive wires ruled faces (edges matched by OCCT, also where the wires
/// have different numbers of edges), the first and the last wire closed by caps, which it names.
/// The wires need not be planar. A null solid when OCCT builds none.
struct RuledSections {
  TopoDS_Shape solid;
  TopoDS_Shape firstCap, lastCap;
};

/// Built by a module of its own (libairshape_ruled_sections.so beside the core), loaded on first
/// use, so that only the processes that loft so load OCCT's offset toolkit (and the fillet and
/// Boolean toolkits it brings: about 5 ms at every start). Throws Error when the module cannot
/// be loaded.
RuledSections ruledThroughSections(const std::vector<TopoDS_Wire>& wires);

}  // namespace airshape::geometry
