#include "airshape/geometry/outer_wires_apart.h"

#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <ShapeFix_Face.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace airshape::geometry {

namespace {

bool hasOuterWiresTogether(const TopoDS_Face& face) {
  const BRepCheck_Analyzer analyzer(face);
  if (analyzer.IsValid()) return false;
  const Handle(BRepCheck_Result)& result = analyzer.Result(face);
  if (result.IsNull()) return false;
  for (BRepCheck_ListIteratorOfListOfStatus status(result->Status()); status.More(); status.Next())
    if (status.Value() == BRepCheck_InvalidImbricationOfWires) return true;
  return false;
}

}  // namespace

std::vector<TopoDS_Face> outerWiresApart(const TopoDS_Face& face) {
  int wires = 0;
  for (TopExp_Explorer wire(face, TopAbs_WIRE); wire.More() && wires < 2; wire.Next()) ++wires;
  if (wires < 2 || !hasOuterWiresTogether(face)) return {face};  // one wire nests nothing
  Handle(ShapeFix_Face) fix = new ShapeFix_Face(face);
  fix->FixSplitFaceMode() = 1;
  fix->Perform();
  std::vector<TopoDS_Face> apart;
  for (TopExp_Explorer part(fix->Result(), TopAbs_FACE); part.More(); part.Next())
    apart.push_back(TopoDS::Face(part.Current()));
  if (apart.empty()) return {face};
  for (const TopoDS_Face& part : apart)
    if (!BRepCheck_Analyzer(part).IsValid()) return {face};  // healing did not help: left for the check to report
  return apart;
}

}  // namespace airshape::geometry
