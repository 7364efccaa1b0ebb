// The ruled loft between two closed profiles, built face by face: each face's edges carry
// their exact lines in the face's parameters, so nothing needs checking or sewing.
#include "airshape/geometry/ruled_loft.h"

#include <cmath>

#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Line.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir2d.hxx>
#include <gp_Pnt2d.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"

namespace airshape::geometry {

namespace {

/// The cap turned, where needed, so that it runs each of its edges against the side face
/// that shares it (a closed shell uses every edge once each way).
TopoDS_Face facingTheSides(TopoDS_Face cap, const TopTools_IndexedDataMapOfShapeListOfShape& facesOfEdges) {
  for (TopExp_Explorer edges(cap, TopAbs_EDGE); edges.More(); edges.Next()) {
    const TopoDS_Shape& edge = edges.Current();
    if (!facesOfEdges.Contains(edge))
      throw Error(ErrorCode::InvalidModel, "the ruled skin does not end on its profiles' edges");
    const TopoDS_Shape& side = facesOfEdges.FindFromKey(edge).First();
    for (TopExp_Explorer sideEdges(side, TopAbs_EDGE); sideEdges.More(); sideEdges.Next())
      if (sideEdges.Current().IsSame(edge))
        return sideEdges.Current().Orientation() == edge.Orientation() ? TopoDS::Face(cap.Reversed()) : cap;
  }
  return cap;
}

/// A closed loop of curves joined end to end, as topology: edge k on curve k, the vertex
/// where the loop enters edge k, and the wire running round.
struct Loop {
  std::vector<TopoDS_Edge> edges;
  std::vector<TopoDS_Vertex> entries;
  TopoDS_Wire wire;
};

/// Whether two curve ends join.
bool meets(const gp_Pnt& a, const gp_Pnt& b) { return a.Distance(b) <= kJoinTolerance; }
/// Where a loop enters and leaves a curve it runs forward or backward.
gp_Pnt entryOf(const Geom_BSplineCurve& curve, bool forward) { return forward ? curve.StartPoint() : curve.EndPoint(); }
gp_Pnt exitOf(const Geom_BSplineCurve& curve, bool forward) { return forward ? curve.EndPoint() : curve.StartPoint(); }

/// Whether a loop can run the curves in these directions: each entered where the one before
/// left, and the last leaving where the first is entered.
bool runsRound(const std::vector<Handle(Geom_BSplineCurve)>& curves, const std::vector<bool>& forward) {
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const std::size_t next = (k + 1) % curves.size();
    if (!meets(exitOf(*curves[k], forward[k]), entryOf(*curves[next], forward[next]))) return false;
  }
  return true;
}

/// The directions in which a loop runs curves joined end to end: the first towards the
/// second, each next one onwards from where the one before ended. Throws Error when they do
/// not join or close.
std::vector<bool> directionsOf(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  const std::size_t n = curves.size();
  std::vector<bool> forward = {n == 1 || meets(curves[0]->EndPoint(), curves[1]->StartPoint()) ||
                               meets(curves[0]->EndPoint(), curves[1]->EndPoint())};
  for (std::size_t k = 1; k < n; ++k) {
    const gp_Pnt exit = exitOf(*curves[k - 1], forward[k - 1]);
    if (!meets(curves[k]->StartPoint(), exit) && !meets(curves[k]->EndPoint(), exit))
      throw Error(ErrorCode::InvalidModel, "a profile's curves do not join end to end");
    forward.push_back(meets(curves[k]->StartPoint(), exit));
  }
  if (!runsRound(curves, forward)) throw Error(ErrorCode::InvalidModel, "a profile's curves do not close");
  return forward;
}

/// The loop running the curves in the given directions. `shared[k]`, where not null, is
/// taken as its entry vertex of curve k (where another loop touches this one).
Loop loopOf(const std::vector<Handle(Geom_BSplineCurve)>& curves, const std::vector<bool>& forward,
            const std::vector<TopoDS_Vertex>& shared = {}) {
  const std::size_t n = curves.size();
  Loop loop;
  std::vector<gp_Pnt> entryPoints;
  for (std::size_t k = 0; k < n; ++k) entryPoints.push_back(entryOf(*curves[k], forward[k]));

  BRep_Builder builder;
  for (std::size_t k = 0; k < n; ++k) {
    TopoDS_Vertex vertex = k < shared.size() ? shared[k] : TopoDS_Vertex();
    if (vertex.IsNull()) builder.MakeVertex(vertex, entryPoints[k], kJoinTolerance);
    loop.entries.push_back(vertex);
  }
  builder.MakeWire(loop.wire);
  for (std::size_t k = 0; k < n; ++k) {
    const TopoDS_Vertex& entry = loop.entries[k];
    const TopoDS_Vertex& leave = loop.entries[(k + 1) % n];
    TopoDS_Edge edge;
    builder.MakeEdge(edge, curves[k], kBrepTolerance);
    builder.Add(edge, (forward[k] ? entry : leave).Oriented(TopAbs_FORWARD));
    builder.Add(edge, (forward[k] ? leave : entry).Oriented(TopAbs_REVERSED));
    builder.Range(edge, curves[k]->FirstParameter(), curves[k]->LastParameter());
    loop.edges.push_back(edge);
    builder.Add(loop.wire, forward[k] ? edge : TopoDS::Edge(edge.Reversed()));
  }
  loop.wire.Closed(true);
  return loop;
}

/// The straight edge from a vertex of one loop to the matching vertex of the other; a
/// degenerate edge (no curve in space, only in the faces' parameters) where the loops share
/// the vertex.
TopoDS_Edge sideEdge(const TopoDS_Vertex& from, const TopoDS_Vertex& to) {
  BRep_Builder builder;
  TopoDS_Edge edge;
  if (from.IsSame(to)) {
    builder.MakeEdge(edge);
    builder.Degenerated(edge, true);
  } else {
    builder.MakeEdge(edge, straightLine(BRep_Tool::Pnt(from), BRep_Tool::Pnt(to)), kBrepTolerance);
  }
  builder.Add(edge, from.Oriented(TopAbs_FORWARD));
  builder.Add(edge, to.Oriented(TopAbs_REVERSED));
  builder.Range(edge, 0.0, 1.0);
  return edge;
}

/// The line u = const of a face's parameter plane, running with v.
Handle(Geom2d_Line) alongV(double u) { return new Geom2d_Line(gp_Pnt2d(u, 0.0), gp_Dir2d(0.0, 1.0)); }

/// The line v = const, running with u.
Handle(Geom2d_Line) alongU(double v) { return new Geom2d_Line(gp_Pnt2d(0.0, v), gp_Dir2d(1.0, 0.0)); }

/// The ruled surface S(u, v) between two curves over the same range (v = 0 on the first) as
/// a face on the edges of those curves and the side edges at the curves' start and end (one
/// seam edge for closed curves). The edges carry their exact lines in (u, v), so, built
/// directly, nothing needs checking (OCCT's ruled skin spent most of its time on that).
TopoDS_Face ruledSideFace(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & last,
                          const TopoDS_Edge& onFirst, const TopoDS_Edge& onLast, const TopoDS_Edge& sideAtStart,
                          const TopoDS_Edge& sideAtEnd) {
  const double u0 = first->FirstParameter(), u1 = first->LastParameter();
  if (std::abs(u0 - last->FirstParameter()) > 1e-12 || std::abs(u1 - last->LastParameter()) > 1e-12)
    throw Error(ErrorCode::InvalidModel, "the two profiles' curves span different parameter ranges");
  BRep_Builder builder;
  TopoDS_Face face;
  builder.MakeFace(face, ruledSurface(first, last), kBrepTolerance);
  builder.UpdateEdge(onFirst, alongU(0.0), face, kBrepTolerance);
  builder.UpdateEdge(onLast, alongU(1.0), face, kBrepTolerance);
  if (sideAtStart.IsSame(sideAtEnd)) {
    builder.UpdateEdge(sideAtEnd, alongV(u1), alongV(u0), face, kBrepTolerance);
  } else {
    builder.UpdateEdge(sideAtStart, alongV(u0), face, kBrepTolerance);
    builder.UpdateEdge(sideAtEnd, alongV(u1), face, kBrepTolerance);
  }
  // Anticlockwise in (u, v): along the first curve, up the end side, back along the last
  // curve, down the start side.
  TopoDS_Wire boundary;
  builder.MakeWire(boundary);
  builder.Add(boundary, onFirst);
  builder.Add(boundary, sideAtEnd);
  builder.Add(boundary, onLast.Reversed());
  builder.Add(boundary, sideAtStart.Reversed());
  boundary.Closed(true);
  builder.Add(face, boundary);
  return face;
}

/// Whether each curve of one profile runs through the same points as its partner on the
/// other (checked at its ends and at a few points between them).
bool profilesCoincide(const std::vector<Handle(Geom_BSplineCurve)>& first,
                      const std::vector<Handle(Geom_BSplineCurve)>& last) {
  constexpr int kSamples = 8;
  for (std::size_t k = 0; k < first.size(); ++k)
    for (int i = 0; i <= kSamples; ++i) {
      const double t = static_cast<double>(i) / kSamples;
      const auto at = [t](const Geom_BSplineCurve& curve) {
        return curve.Value(curve.FirstParameter() + t * (curve.LastParameter() - curve.FirstParameter()));
      };
      if (at(*first[k]).Distance(at(*last[k])) > kBrepTolerance) return false;
    }
  return true;
}

}  // namespace

RuledLoft ruledLoft(const std::vector<Handle(Geom_BSplineCurve)>& first,
                    const std::vector<Handle(Geom_BSplineCurve)>& last) {
  if (first.empty() || first.size() != last.size())
    throw Error(ErrorCode::InvalidModel, "the two profiles have different numbers of curves");
  // Both loops run their curves the same way; a curve shrunk to a point runs either way,
  // so one loop may take the other's directions.
  std::vector<bool> forward = directionsOf(first);
  if (const std::vector<bool> other = directionsOf(last); other != forward) {
    if (!runsRound(last, forward)) {
      if (!runsRound(first, other)) throw Error(ErrorCode::InvalidModel, "the two profiles run differently");
      forward = other;
    }
  }
  const Loop a = loopOf(first, forward);
  const std::size_t n = first.size();
  // Where the profiles touch (a segment tapering to a point, or of no length), the second
  // loop takes the first one's vertex and the side edge there degenerates.
  std::vector<TopoDS_Vertex> touching(n);
  for (std::size_t k = 0; k < n; ++k)
    if (meets(BRep_Tool::Pnt(a.entries[k]), entryOf(*last[k], forward[k]))) touching[k] = a.entries[k];
  const Loop b = loopOf(last, forward, touching);
  std::vector<TopoDS_Edge> sides;
  for (std::size_t k = 0; k < n; ++k) sides.push_back(sideEdge(a.entries[k], b.entries[k]));

  BRep_Builder builder;
  RuledLoft loft;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (std::size_t k = 0; k < n; ++k) {
    const TopoDS_Edge& entrySide = sides[k];
    const TopoDS_Edge& leaveSide = sides[(k + 1) % n];
    const TopoDS_Face face = ruledSideFace(first[k], last[k], a.edges[k], b.edges[k],
                                           forward[k] ? entrySide : leaveSide, forward[k] ? leaveSide : entrySide);
    // Where the loop runs against the curve, the face turns too, so that each side edge is
    // run once each way by the two faces that share it.
    loft.sides.push_back(forward[k] ? face : TopoDS::Face(face.Reversed()));
    builder.Add(shell, loft.sides.back());
  }
  // The lines in the faces' parameters run over the edges' ranges (a degenerate side edge
  // has no other curve to take its range from).
  for (const TopoDS_Edge& side : sides) builder.Range(side, 0.0, 1.0);
  for (std::size_t k = 0; k < n; ++k) {
    builder.Range(a.edges[k], first[k]->FirstParameter(), first[k]->LastParameter());
    builder.Range(b.edges[k], last[k]->FirstParameter(), last[k]->LastParameter());
  }
  TopTools_IndexedDataMapOfShapeListOfShape facesOfEdges;
  TopExp::MapShapesAndAncestors(shell, TopAbs_EDGE, TopAbs_FACE, facesOfEdges);
  // The caps lie on the profiles' own edges, turned against the sides.
  loft.firstCap = facingTheSides(planarFace(a.wire), facesOfEdges);
  loft.lastCap = facingTheSides(planarFace(b.wire), facesOfEdges);
  builder.Add(shell, loft.firstCap);
  builder.Add(shell, loft.lastCap);
  shell.Closed(true);
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  // Two different profiles in one plane bound a flat ring of no volume, which the reference
  // builds too (CPACS_30_D250_10.xml's main surface steps from its tip airfoil to a smaller one
  // there); only coinciding profiles, a segment of no length, are refused.
  if (profilesCoincide(first, last))
    throw Error(ErrorCode::InvalidModel, "the faces enclose no volume (the two profiles coincide)");
  loft.solid = outwards(solid, FlatSolid::Kept);
  return loft;
}

}  // namespace airshape::geometry
