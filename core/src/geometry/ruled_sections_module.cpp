// OCCT's ruled loft through sections (and its ruled face between two edges) in a module of its own
// (libairshape_ruled_sections.so, beside the core), loaded only when something lofts so (control devices, cells,
// revolved cowls): OCCT's offset toolkit and the fillet and Boolean toolkits it links are built with BIND_NOW on
// Debian, and loading them with the plugins cost every process about 5 ms.
#include <vector>

#include <BRepFill.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

/// The module's entry: the ruled solid through the wires and its two caps (null when OCCT builds
/// none; OCCT's exceptions are caught here, as its result is then unusable).
extern "C" __attribute__((visibility("default"))) void airshape_ruled_sections(const std::vector<TopoDS_Wire>& wires,
                                                                               TopoDS_Shape& solid,
                                                                               TopoDS_Shape& firstCap,
                                                                               TopoDS_Shape& lastCap) {
  solid.Nullify();
  try {
    BRepOffsetAPI_ThruSections loft(true, true);
    for (const TopoDS_Wire& wire : wires) loft.AddWire(wire);
    loft.Build();
    if (!loft.IsDone()) return;
    solid = loft.Shape();
    firstCap = loft.FirstShape();
    lastCap = loft.LastShape();
  } catch (const Standard_Failure&) {
    solid.Nullify();
  }
}

/// The module's second entry: OCCT's ruled face between two edges (null when OCCT builds none).
extern "C" __attribute__((visibility("default"))) void airshape_ruled_face(const TopoDS_Edge& first,
                                                                           const TopoDS_Edge& second,
                                                                           TopoDS_Face& face) {
  face.Nullify();
  try {
    face = BRepFill::Face(first, second);
  } catch (const Standard_Failure&) {
    face.Nullify();
  }
}
