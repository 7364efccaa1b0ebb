#include "skin_section.h"

#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pln.hxx>

namespace airshape::structure {

namespace {

/// The edges along a skin crossing, from `start` over a vertex at each piece's end; the last
/// vertex is returned in `end`.
std::vector<TopoDS_Edge> crossingEdges(const SkinCrossing& crossing, const TopoDS_Vertex& start, TopoDS_Vertex& end) {
  std::vector<TopoDS_Edge> edges;
  TopoDS_Vertex from = start;
  for (const Handle(Geom_BSplineCurve) & piece : crossing.pieces) {
    const TopoDS_Vertex to = BRepBuilderAPI_MakeVertex(piece->EndPoint());
    edges.push_back(BRepBuilderAPI_MakeEdge(piece, from, to));
    from = to;
  }
  end = from;
  return edges;
}

/// Whether the skins end in straight edges that lie in one plane (a flat blunt trailing edge):
/// whatever surface closes the wing between them is that plane, and the section crosses it in
/// a straight line.
bool flatBetween(const std::optional<SkinCrossing::StraightEdge>& top,
                 const std::optional<SkinCrossing::StraightEdge>& bottom, double tolerance) {
  if (!top || !bottom) return false;
  const gp_Vec normal = gp_Vec(top->first, top->second).Crossed(gp_Vec(top->first, bottom->first));
  if (normal.Magnitude() <= 1e-300) return false;
  return std::abs(gp_Vec(top->first, bottom->second).Dot(normal.Normalized())) <= tolerance;
}

}  // namespace

std::optional<TopoDS_Face> sectionBetweenSkins(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                               const CrossingLines& lines, const CrossingEnd& from,
                                               const CrossingEnd& to, double tolerance, OpenEnds openEnds) {
  const auto upper = traceSkinCrossing(upperSkin, lines, from, to, tolerance);
  const auto lower = traceSkinCrossing(lowerSkin, lines, from, to, tolerance);
  if (!upper || !lower) return std::nullopt;
  // At each end the skins' crossings either meet (a sharp edge of the wing, where an open end
  // of a rib lies) or are joined by a straight line (a line of the plane, or a flat end cap).
  const bool startsTogether = upper->start().Distance(lower->start()) <= tolerance;
  const bool endsTogether = upper->end().Distance(lower->end()) <= tolerance;
  const auto closable = [&](const CrossingEnd& end, bool together, const std::optional<SkinCrossing::StraightEdge>& top,
                            const std::optional<SkinCrossing::StraightEdge>& bottom) {
    if (end.kind != CrossingEnd::Kind::Open) return !together;
    return together || openEnds == OpenEnds::ClosedStraight || flatBetween(top, bottom, tolerance);
  };
  if (!closable(from, startsTogether, upper->startEdge, lower->startEdge) ||
      !closable(to, endsTogether, upper->endEdge, lower->endEdge))
    return std::nullopt;
  const TopoDS_Vertex upperStart = BRepBuilderAPI_MakeVertex(upper->start());
  const TopoDS_Vertex lowerStart =
      startsTogether ? upperStart : TopoDS_Vertex(BRepBuilderAPI_MakeVertex(lower->start()));
  TopoDS_Vertex upperEnd, lowerEnd;
  const std::vector<TopoDS_Edge> upperEdges = crossingEdges(*upper, upperStart, upperEnd);
  std::vector<TopoDS_Edge> lowerEdges = crossingEdges(*lower, lowerStart, lowerEnd);
  if (endsTogether) {  // the lower crossing's last edge ends at the upper's last vertex
    const Handle(Geom_BSplineCurve)& last = lower->pieces.back();
    const TopoDS_Vertex lastStart =
        lowerEdges.size() > 1 ? TopExp::LastVertex(lowerEdges[lowerEdges.size() - 2], true) : lowerStart;
    lowerEdges.back() = BRepBuilderAPI_MakeEdge(last, lastStart, upperEnd);
    lowerEnd = upperEnd;
  }
  BRepBuilderAPI_MakeWire outline;
  for (const TopoDS_Edge& edge : upperEdges) outline.Add(edge);
  if (!endsTogether) outline.Add(BRepBuilderAPI_MakeEdge(upperEnd, lowerEnd).Edge());
  for (auto edge = lowerEdges.rbegin(); edge != lowerEdges.rend(); ++edge) outline.Add(TopoDS::Edge(edge->Reversed()));
  if (!startsTogether) outline.Add(BRepBuilderAPI_MakeEdge(lowerStart, upperStart).Edge());
  if (!outline.IsDone()) return std::nullopt;
  BRepBuilderAPI_MakeFace face(gp_Pln(lines.origin, lines.planeNormal()), outline.Wire(), true);
  if (!face.IsDone()) return std::nullopt;
  return face.Face();
}

}  // namespace airshape::structure
