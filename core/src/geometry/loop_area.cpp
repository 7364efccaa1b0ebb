#include "airshape/geometry/loop_area.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <BRepAdaptor_Curve.hxx>
#include <ElSLib.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt2d.hxx>

#include "airshape/geometry/brep_measures.h"

namespace airshape::geometry {

namespace {

/// Points along a closed line in the plane's own 2D coordinates: 32 per edge.
std::vector<gp_Pnt2d> outlineIn(const gp_Pln& plane, const TopoDS_Wire& loop) {
  constexpr int kPointsPerEdge = 32;
  std::vector<gp_Pnt2d> outline;
  for (TopExp_Explorer explorer(loop, TopAbs_EDGE); explorer.More(); explorer.Next()) {
    const BRepAdaptor_Curve edge(TopoDS::Edge(explorer.Current()));
    for (int i = 0; i < kPointsPerEdge; ++i) {
      const gp_Pnt p =
          edge.Value(edge.FirstParameter() + (edge.LastParameter() - edge.FirstParameter()) * i / kPointsPerEdge);
      double x, y;
      ElSLib::Parameters(plane, p, x, y);
      outline.emplace_back(x, y);
    }
  }
  return outline;
}

/// Whether a point lies inside a closed polygon (crossings of a ray along +x).
bool inside(const gp_Pnt2d& point, const std::vector<gp_Pnt2d>& polygon) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const gp_Pnt2d &a = polygon[i], &b = polygon[j];
    if ((a.Y() > point.Y()) != (b.Y() > point.Y()) &&
        point.X() < a.X() + (b.X() - a.X()) * (point.Y() - a.Y()) / (b.Y() - a.Y()))
      in = !in;
  }
  return in;
}

/// Which side of the line from a to b the point c lies on: +1, -1, or 0 on it.
int sideOf(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& c) {
  const double cross = (b.X() - a.X()) * (c.Y() - a.Y()) - (b.Y() - a.Y()) * (c.X() - a.X());
  return cross > 0.0 ? 1 : (cross < 0.0 ? -1 : 0);
}

/// Whether p, on the line through a and b, lies between them.
bool within(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& p) {
  return std::min(a.X(), b.X()) <= p.X() && p.X() <= std::max(a.X(), b.X()) && std::min(a.Y(), b.Y()) <= p.Y() &&
         p.Y() <= std::max(a.Y(), b.Y());
}

/// Whether two segments meet: cross, or touch (an end of one on the other).
bool meet(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& c, const gp_Pnt2d& d) {
  const int c1 = sideOf(a, b, c), d1 = sideOf(a, b, d), a2 = sideOf(c, d, a), b2 = sideOf(c, d, b);
  if (c1 * d1 < 0 && a2 * b2 < 0) return true;
  return (c1 == 0 && within(a, b, c)) || (d1 == 0 && within(a, b, d)) || (a2 == 0 && within(c, d, a)) ||
         (b2 == 0 && within(c, d, b));
}

/// Whether the outlines cross or touch themselves or each other: then they bound no regions
/// one inside another (a solid that passes through itself, or touches itself along the plane).
bool anyCrossing(const std::vector<std::vector<gp_Pnt2d>>& outlines) {
  struct Segment {
    std::size_t outline, index;
    gp_Pnt2d from, to;
  };
  std::vector<Segment> segments;
  for (std::size_t k = 0; k < outlines.size(); ++k)
    for (std::size_t i = 0; i < outlines[k].size(); ++i)
      segments.push_back({k, i, outlines[k][i], outlines[k][(i + 1) % outlines[k].size()]});
  const auto low = [](const Segment& s) { return std::min(s.from.X(), s.to.X()); };
  const auto high = [](const Segment& s) { return std::max(s.from.X(), s.to.X()); };
  // Swept along x: a segment meets only those that start before it ends.
  std::sort(segments.begin(), segments.end(), [&](const Segment& a, const Segment& b) { return low(a) < low(b); });
  for (std::size_t m = 0; m < segments.size(); ++m)
    for (std::size_t n = m + 1; n < segments.size() && low(segments[n]) <= high(segments[m]); ++n) {
      const Segment &s = segments[m], &t = segments[n];
      const std::size_t size = outlines[s.outline].size();
      const bool neighbours =
          s.outline == t.outline && ((s.index + 1) % size == t.index || (t.index + 1) % size == s.index);
      if (!neighbours && meet(s.from, s.to, t.from, t.to)) return true;
    }
  return false;
}

}  // namespace

std::optional<double> areaInsideLoops(const gp_Pln& plane, const std::vector<TopoDS_Wire>& loops) {
  std::vector<std::vector<gp_Pnt2d>> outlines;
  for (const TopoDS_Wire& loop : loops) outlines.push_back(outlineIn(plane, loop));
  if (anyCrossing(outlines)) return std::nullopt;
  double area = 0.0;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    int depth = 0;
    for (std::size_t j = 0; j < loops.size(); ++j)
      if (j != i && !outlines[i].empty() && inside(outlines[i].front(), outlines[j])) ++depth;
    const double own = std::abs(signedAreaEnclosed(loops[i], plane.Axis().Direction()));
    area += depth % 2 == 0 ? own : -own;
  }
  return area;
}

}  // namespace airshape::geometry
