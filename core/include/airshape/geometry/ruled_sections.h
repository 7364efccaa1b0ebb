#pragma once

#include <vector>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

namespace airshape::geometry {

/// The solid of OCCT's ruled loft through closed wires (BRepOffsetAPI_ThruSections, ruled):
/// between each two consecutive wires ruled faces (edges matched by OCCT, also where the wires
/// have different numbers of edges), the first and the last wire closed by caps, which it names.
/// The wires need not be planar. Ruled faces that are flat (to a billionth of the loft's size)
/// are made plane faces with the same edges, which OCCT's Booleans cut far faster. A null
/// solid when OCCT builds none.
struct RuledSections {
  TopoDS_Shape solid;
  TopoDS_Shape firstCap, lastCap;
};

/// Built by a module of its own (libairshape_ruled_sections.so beside the core), loaded on first
/// use, so that only the processes that loft so load OCCT's offset toolkit (and the fillet and
/// Boolean toolkits it brings: about 5 ms at every start). Throws Error when the module cannot
/// be loaded.
RuledSections ruledThroughSections(const std::vector<TopoDS_Wire>& wires);

/// OCCT's ruled face between two edges (BRepFill::Face: points of equal share of each edge's
/// parameter range joined), from the same module. A null face when OCCT builds none.
TopoDS_Face ruledFaceBetween(const TopoDS_Edge& first, const TopoDS_Edge& second);

}  // namespace airshape::geometry
