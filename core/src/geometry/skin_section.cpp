#include "airshape/geometry/skin_section.h"

#include <cmath>
#include <utility>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pln.hxx>

namespace airshape::geometry {

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

/// The curve where a plane meets the ruled face between two straight edges of the skins (the
/// blunt trailing edge between the upper and the lower skin's last lines: a bilinear patch
/// with its corners matched), from the upper edge (w = 0) to the lower (w = 1): with the upper
/// line A(l) = A0 + l dA and the lower B(l) = B0 + l dB, n . ((1 - w) A(l) + w B(l)) = d gives
/// l = -N(w) / D(w), both linear in w, so the curve is a rational quadratic, exact as a
/// B-spline with weights. Nothing when the plane runs along the edges.
std::optional<Handle(Geom_BSplineCurve)> acrossBluntEdge(const SkinCrossing::StraightEdge& top,
                                                         SkinCrossing::StraightEdge bottom, const gp_Pln& plane) {
  const auto apart = [](const SkinCrossing::StraightEdge& a, const SkinCrossing::StraightEdge& b) {
    return a.first.Distance(b.first) + a.second.Distance(b.second);
  };
  if (apart(top, bottom) > apart(top, {bottom.second, bottom.first})) std::swap(bottom.first, bottom.second);
  const gp_XYZ n = plane.Axis().Direction().XYZ();
  const double level = n.Dot(plane.Location().XYZ());
  const gp_XYZ a0 = top.first.XYZ(), dA = top.second.XYZ() - a0;
  const gp_XYZ b0 = bottom.first.XYZ(), dB = bottom.second.XYZ() - b0;
  const double nA = n.Dot(a0) - level, nB = n.Dot(b0) - level;  // N(0), N(1)
  double dA0 = n.Dot(dA), dB0 = n.Dot(dB);                      // D(0), D(1)
  if (std::abs(dA0) < 1e-12 * dA.Modulus() || std::abs(dB0) < 1e-12 * dB.Modulus() || (dA0 < 0.0) != (dB0 < 0.0))
    return std::nullopt;
  // The homogeneous poles D(w) ((1 - w) A0 + w B0) - N(w) ((1 - w) dA + w dB), in Bernstein form.
  const gp_XYZ h0 = dA0 * a0 - nA * dA, h2 = dB0 * b0 - nB * dB;
  const gp_XYZ h1 = 0.5 * (dA0 * b0 + dB0 * a0) - 0.5 * (nA * dB + nB * dA);
  const double w0 = dA0, w1 = 0.5 * (dA0 + dB0), w2 = dB0;
  TColgp_Array1OfPnt poles(1, 3);
  poles.SetValue(1, gp_Pnt(h0 / w0));
  poles.SetValue(2, gp_Pnt(h1 / w1));
  poles.SetValue(3, gp_Pnt(h2 / w2));
  TColStd_Array1OfReal weights(1, 3);
  weights.SetValue(1, std::abs(w0));
  weights.SetValue(2, std::abs(w1));
  weights.SetValue(3, std::abs(w2));
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(3);
  return Handle(Geom_BSplineCurve)(new Geom_BSplineCurve(poles, weights, knots, multiplicities, 2));
}

/// Whether the skins end in straight edges that lie in one plane (a flat blunt trailing edge):
/// whatever surface closes the lifting surface between them is that plane, and the section crosses it in
/// a straight line.
bool flatBetween(const std::optional<SkinCrossing::StraightEdge>& top,
                 const std::optional<SkinCrossing::StraightEdge>& bottom, double tolerance) {
  if (!top || !bottom) return false;
  const gp_Vec normal = gp_Vec(top->first, top->second).Crossed(gp_Vec(top->first, bottom->first));
  if (normal.Magnitude() <= 1e-300) return false;
  return std::abs(gp_Vec(top->first, bottom->second).Dot(normal.Normalized())) <= tolerance;
}

/// The edge closing a section at one end, from the upper skin's crossing to the lower's: the
/// straight line, or across a twisted blunt edge the conic (nothing when that does not meet
/// the crossings' ends within the tolerance).
std::optional<TopoDS_Edge> closingEdge(const TopoDS_Vertex& upper, const TopoDS_Vertex& lower, bool straight,
                                       const std::optional<SkinCrossing::StraightEdge>& top,
                                       const std::optional<SkinCrossing::StraightEdge>& bottom, const gp_Pln& plane,
                                       double tolerance) {
  if (straight) return BRepBuilderAPI_MakeEdge(upper, lower).Edge();
  const auto curve = acrossBluntEdge(*top, *bottom, plane);
  if (!curve || (*curve)->StartPoint().Distance(BRep_Tool::Pnt(upper)) > tolerance ||
      (*curve)->EndPoint().Distance(BRep_Tool::Pnt(lower)) > tolerance)
    return std::nullopt;
  BRepBuilderAPI_MakeEdge edge(*curve, upper, lower);
  if (!edge.IsDone()) return std::nullopt;
  return edge.Edge();
}

}  // namespace

std::optional<TopoDS_Face> sectionBetweenSkins(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                               const CrossingLines& lines, const CrossingEnd& from,
                                               const CrossingEnd& to, double tolerance, OpenEnds openEnds) {
  const auto upper = traceSkinCrossing(upperSkin, lines, from, to, tolerance);
  const auto lower = traceSkinCrossing(lowerSkin, lines, from, to, tolerance);
  if (!upper || !lower) return std::nullopt;
  // At each end the skins' crossings either meet (a sharp edge of the lifting surface, where an open end
  // of a plate lies) or are joined: by a straight line (a line of the plane, a flat end cap) or
  // by the curve across a twisted blunt edge.
  const bool startsTogether = upper->start().Distance(lower->start()) <= tolerance;
  const bool endsTogether = upper->end().Distance(lower->end()) <= tolerance;
  enum class Closure { None, Straight, Twisted, Impossible };
  const auto closure = [&](const CrossingEnd& end, bool together, const std::optional<SkinCrossing::StraightEdge>& top,
                           const std::optional<SkinCrossing::StraightEdge>& bottom) {
    if (end.kind != CrossingEnd::Kind::Open) return together ? Closure::Impossible : Closure::Straight;
    if (together) return Closure::None;
    if (openEnds == OpenEnds::ClosedStraight || flatBetween(top, bottom, tolerance)) return Closure::Straight;
    return top && bottom ? Closure::Twisted : Closure::Impossible;
  };
  const Closure atStart = closure(from, startsTogether, upper->startEdge, lower->startEdge);
  const Closure atEnd = closure(to, endsTogether, upper->endEdge, lower->endEdge);
  if (atStart == Closure::Impossible || atEnd == Closure::Impossible) return std::nullopt;
  const gp_Pln plane(lines.origin, lines.planeNormal());
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
  if (atEnd != Closure::None) {
    const auto edge =
        closingEdge(upperEnd, lowerEnd, atEnd == Closure::Straight, upper->endEdge, lower->endEdge, plane, tolerance);
    if (!edge) return std::nullopt;
    outline.Add(*edge);
  }
  for (auto edge = lowerEdges.rbegin(); edge != lowerEdges.rend(); ++edge) outline.Add(TopoDS::Edge(edge->Reversed()));
  if (atStart != Closure::None) {
    const auto edge = closingEdge(upperStart, lowerStart, atStart == Closure::Straight, upper->startEdge,
                                  lower->startEdge, plane, tolerance);
    if (!edge) return std::nullopt;
    outline.Add(TopoDS::Edge(edge->Reversed()));
  }
  if (!outline.IsDone()) return std::nullopt;
  BRepBuilderAPI_MakeFace face(plane, outline.Wire(), true);
  if (!face.IsDone()) return std::nullopt;
  return face.Face();
}

}  // namespace airshape::geometry
