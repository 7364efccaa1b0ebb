#include "airshape/query/box_answer.h"

#include <BRepBndLib.hxx>

namespace airshape::query {

Bnd_Box tightBox(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  return box;
}

Json boxAnswer(const Bnd_Box& box) {
  double x1, y1, z1, x2, y2, z2;
  box.Get(x1, y1, z1, x2, y2, z2);
  return {{"min", {x1, y1, z1}}, {"max", {x2, y2, z2}}};
}

}  // namespace airshape::query
