#include "airshape/query/box_answer.h"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include <BRepBndLib.hxx>
#include <TopExp_Explorer.hxx>

namespace airshape::query {

namespace {

/// The faces of a shape, its edges outside faces and its vertices outside edges: what its box
/// is the union of.
std::vector<TopoDS_Shape> partsOf(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Shape> parts;
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next()) parts.push_back(face.Current());
  for (TopExp_Explorer edge(shape, TopAbs_EDGE, TopAbs_FACE); edge.More(); edge.Next()) parts.push_back(edge.Current());
  for (TopExp_Explorer vertex(shape, TopAbs_VERTEX, TopAbs_EDGE); vertex.More(); vertex.Next())
    parts.push_back(vertex.Current());
  return parts;
}

/// A box's six bounds: x, y, z low, then x, y, z high.
std::array<double, 6> boundsOf(const Bnd_Box& box) {
  std::array<double, 6> b{};
  box.Get(b[0], b[1], b[2], b[3], b[4], b[5]);
  return b;
}

}  // namespace

Bnd_Box tightBox(const TopoDS_Shape& shape) {
  // OCCT's exact box of a part searches its surface for extremes, seconds on a lofted body of
  // many-knotted skins. Only the parts that may hold one of the six extremes need it: a
  // part's box from its control points bounds it, so once a part's exact bound reaches beyond
  // every other part's rough one in a direction, no other part matters there.
  const std::vector<TopoDS_Shape> parts = partsOf(shape);
  std::vector<std::array<double, 6>> rough;
  for (const TopoDS_Shape& part : parts) {
    Bnd_Box box;
    BRepBndLib::Add(part, box, false);
    rough.push_back(box.IsVoid() ? std::array<double, 6>{} : boundsOf(box));
  }
  std::vector<std::optional<Bnd_Box>> exact(parts.size());
  Bnd_Box tight;
  for (int bound = 0; bound < 6; ++bound) {
    const bool high = bound >= 3;
    // The parts in the order their rough bounds reach out, farthest first.
    std::vector<std::size_t> order(parts.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return high ? rough[a][bound] > rough[b][bound] : rough[a][bound] < rough[b][bound];
    });
    std::optional<double> reached;
    for (std::size_t k : order) {
      if (reached && (high ? rough[k][bound] <= *reached : rough[k][bound] >= *reached)) break;
      if (!exact[k]) {
        exact[k].emplace();
        BRepBndLib::AddOptimal(parts[k], *exact[k], false, false);
      }
      if (exact[k]->IsVoid()) continue;
      tight.Add(*exact[k]);
      const double at = boundsOf(*exact[k])[bound];
      if (!reached || (high ? at > *reached : at < *reached)) reached = at;
    }
  }
  return tight;
}

Json boxAnswer(const Bnd_Box& box) {
  double x1, y1, z1, x2, y2, z2;
  box.Get(x1, y1, z1, x2, y2, z2);
  return {{"min", {x1, y1, z1}}, {"max", {x2, y2, z2}}};
}

}  // namespace airshape::query
