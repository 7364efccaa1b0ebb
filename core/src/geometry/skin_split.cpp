#include "airshape/geometry/skin_split.h"

#include <algorithm>
#include <cmath>

#include <BOPAlgo_BuilderFace.hxx>
#include <BOPTools_AlgoTools.hxx>
#include <BOPTools_AlgoTools3D.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAPI_ProjectPointOnCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <IntTools_Context.hxx>
#include <NCollection_DataMap.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt2d.hxx>

#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/bspline_patch.h"
#include "airshape/geometry/ruled_crossing.h"

namespace airshape::geometry {

namespace {

/// Whether a piece runs along one of its patch's bounds (a border of the region on an edge the
/// skin has already): no curve is needed there.
bool alongBound(const Patch& patch, const CrossingPiece& piece) {
  auto all = [&](auto on) { return std::all_of(piece.points.begin(), piece.points.end(), on); };
  return all([&](const PatchPoint& p) { return p.u == patch.u0; }) ||
         all([&](const PatchPoint& p) { return p.u == patch.u1; }) ||
         all([&](const PatchPoint& p) { return p.v == patch.v0; }) ||
         all([&](const PatchPoint& p) { return p.v == patch.v1; });
}

/// A crossing piece drawn on its patch: the curve in the patch's parameters over [first, last]
/// and its ends.
struct Drawn {
  std::size_t patch = 0;
  Handle(Geom2d_BSplineCurve) curve;
  PatchPoint start, end;
};

/// The crossings of the loop's sides with the skin, drawn on its patches (pieces along a
/// patch's bound left out: the skin has an edge there already). Throws FoldedSkin.
std::optional<std::vector<Drawn>> crossingsOf(const std::vector<Patch>& patches, const RuledLoop& loop,
                                              double tolerance) {
  const std::size_t n = loop.points.size();
  std::vector<Drawn> drawn;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    const RuledLines side{loop.points[k], loop.points[next], loop.directions[k], loop.directions[next], loop.rays};
    const auto pieces = ruledCrossing(patches, side, tolerance);
    if (!pieces) return std::nullopt;
    for (const CrossingPiece& piece : *pieces) {
      // Ends on a bound lie on it exactly, so that the curve splits the face there.
      const Patch& patch = patches[piece.patch];
      if (!alongBound(patch, piece))
        drawn.push_back({piece.patch, piece.curve, ontoBound(patch, piece.points.front(), tolerance),
                         ontoBound(patch, piece.points.back(), tolerance)});
    }
  }
  return drawn;
}

/// The vertices of the split: the skin's own where a crossing ends on one, new ones elsewhere,
/// each point given one vertex.
class VertexPool {
 public:
  VertexPool(const TopoDS_Shape& skin, double tolerance) : tolerance_(tolerance) {
    for (TopExp_Explorer vertex(skin, TopAbs_VERTEX); vertex.More(); vertex.Next())
      known_.push_back(TopoDS::Vertex(vertex.Current()));
  }

  /// The vertex at a point; `isNew` says whether the skin had none there.
  TopoDS_Vertex at(const gp_Pnt& point, bool& isNew) {
    for (const TopoDS_Vertex& vertex : known_)
      if (BRep_Tool::Pnt(vertex).Distance(point) <= std::max(tolerance_, BRep_Tool::Tolerance(vertex))) {
        isNew = made_.Contains(vertex);
        return vertex;
      }
    const TopoDS_Vertex vertex = geometry::vertexWithin(point, tolerance_);
    known_.push_back(vertex);
    made_.Add(vertex);
    isNew = true;
    return vertex;
  }

 private:
  double tolerance_;
  std::vector<TopoDS_Vertex> known_;
  TopTools_IndexedMapOfShape made_;
};

/// Where new vertices split the skin's edges: by edge, the parameters and vertices.
using EdgeSplits =
    NCollection_DataMap<TopoDS_Shape, std::vector<std::pair<double, TopoDS_Vertex>>, TopTools_ShapeMapHasher>;

/// Records where a new vertex at a point of a face's bound (parameters `uv`) splits the face's
/// edge there.
void splitEdgeAt(const TopoDS_Face& face, const gp_Pnt2d& uv, const TopoDS_Vertex& vertex, double tolerance,
                 EdgeSplits& splits) {
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) curve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (curve.IsNull()) continue;
    Geom2dAPI_ProjectPointOnCurve projection(uv, curve, first, last);
    if (projection.NbPoints() == 0) continue;
    const double parameter = projection.LowerDistanceParameter();
    const gp_Pnt onEdge = BRep_Tool::Curve(edge, first, last)->Value(parameter);
    if (onEdge.Distance(BRep_Tool::Pnt(vertex)) > BRep_Tool::Tolerance(vertex) + tolerance) continue;
    if (!splits.IsBound(edge)) splits.Bind(edge, {});
    splits.ChangeFind(edge).emplace_back(parameter, vertex);
    return;
  }
}

/// The pieces of a split edge, in order along it, each as the edge is oriented.
std::vector<TopoDS_Edge> piecesOfEdge(const TopoDS_Edge& edge, std::vector<std::pair<double, TopoDS_Vertex>> cuts) {
  const TopoDS_Edge forward = TopoDS::Edge(edge.Oriented(TopAbs_FORWARD));
  TopoDS_Vertex start, end;
  TopExp::Vertices(forward, start, end);
  double first = 0, last = 0;
  BRep_Tool::Range(forward, first, last);
  std::sort(cuts.begin(), cuts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  cuts.insert(cuts.begin(), {first, start});
  cuts.emplace_back(last, end);
  std::vector<TopoDS_Edge> pieces;
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    if (cuts[i].first - cuts[i - 1].first <= 1e-12 * (last - first)) continue;
    TopoDS_Edge piece;
    BOPTools_AlgoTools::MakeSplitEdge(forward, cuts[i - 1].second, cuts[i - 1].first, cuts[i].second, cuts[i].first,
                                      piece);
    pieces.push_back(TopoDS::Edge(piece.Oriented(edge.Orientation())));
  }
  return pieces;
}

/// The skin's faces split along the drawn crossings: each face rebuilt from its edges (split
/// where crossings end on them) and the crossings on it; nothing when a face cannot be built.
std::optional<std::vector<TopoDS_Face>> splitFaces(const std::vector<TopoDS_Face>& faces,
                                                   const std::vector<Patch>& patches, const std::vector<Drawn>& drawn,
                                                   const TopoDS_Shape& skin, double tolerance) {
  VertexPool vertices(skin, 10.0 * tolerance);
  EdgeSplits splits;
  std::vector<std::vector<TopoDS_Edge>> inside(faces.size());
  for (const Drawn& crossing : drawn) {
    const TopoDS_Face& face = faces[crossing.patch];
    TopoDS_Vertex ends[2];
    const PatchPoint* points[2] = {&crossing.start, &crossing.end};
    for (int e = 0; e < 2; ++e) {
      bool isNew = false;
      ends[e] = vertices.at(points[e]->point, isNew);
      const Patch& patch = patches[crossing.patch];
      const bool onBound =
          points[e]->u == patch.u0 || points[e]->u == patch.u1 || points[e]->v == patch.v0 || points[e]->v == patch.v1;
      if (isNew && onBound) splitEdgeAt(face, gp_Pnt2d(points[e]->u, points[e]->v), ends[e], tolerance, splits);
    }
    BRepBuilderAPI_MakeEdge edge(crossing.curve, patches[crossing.patch].surface, ends[0], ends[1], crossing.start.t,
                                 crossing.end.t);
    if (!edge.IsDone()) return std::nullopt;
    TopoDS_Edge made = edge.Edge();
    BRep_Builder().UpdateEdge(made, crossing.curve, face, 10.0 * tolerance);
    if (!BRepLib::BuildCurve3d(made, tolerance)) return std::nullopt;
    inside[crossing.patch].push_back(made);
  }
  std::vector<TopoDS_Face> result;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const TopoDS_Face forward = TopoDS::Face(faces[k].Oriented(TopAbs_FORWARD));
    bool touched = !inside[k].empty();
    TopTools_ListOfShape edges;
    for (TopExp_Explorer it(forward, TopAbs_EDGE); it.More(); it.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
      if (!splits.IsBound(edge)) {
        edges.Append(edge);
        continue;
      }
      touched = true;
      for (const TopoDS_Edge& piece : piecesOfEdge(edge, splits.Find(edge))) edges.Append(piece);
    }
    if (!touched) {
      result.push_back(faces[k]);
      continue;
    }
    for (const TopoDS_Edge& edge : inside[k]) {
      edges.Append(edge.Oriented(TopAbs_FORWARD));
      edges.Append(edge.Oriented(TopAbs_REVERSED));
    }
    BOPAlgo_BuilderFace builder;
    builder.SetFace(forward);
    builder.SetShapes(edges);
    builder.Perform();
    if (builder.HasErrors() || builder.Areas().IsEmpty()) return std::nullopt;
    for (const TopoDS_Shape& area : builder.Areas())
      result.push_back(TopoDS::Face(area.Oriented(faces[k].Orientation())));
  }
  return result;
}

/// The split skin (skinSplitByLoop), throwing FoldedSkin or OCCT's failures where the direct
/// way does not apply.
std::optional<std::vector<TopoDS_Face>> splitByLoop(const TopoDS_Shape& skin, const RuledLoop& loop, double tolerance) {
  const auto patches = skinPatches(skin);
  if (!patches) return std::nullopt;
  const auto drawn = crossingsOf(patches->patches, loop, tolerance);
  if (!drawn) return std::nullopt;
  return splitFaces(patches->faces, patches->patches, *drawn, skin, tolerance);
}

}  // namespace

std::optional<std::vector<TopoDS_Face>> skinSplitByLoop(const TopoDS_Shape& skin, const RuledLoop& loop,
                                                        double tolerance) {
  try {
    return splitByLoop(skin, loop, tolerance);
  } catch (const FoldedSkin&) {
    return std::nullopt;
  } catch (const Standard_Failure&) {  // a curve or face OCCT cannot make: the Boolean way then
    return std::nullopt;
  }
}

std::optional<std::vector<TopoDS_Face>> skinPiecesWhere(const TopoDS_Shape& skin, const RuledLoop& loop,
                                                        const std::function<bool(const gp_Pnt&)>& keep,
                                                        double tolerance) {
  const auto split = skinSplitByLoop(skin, loop, tolerance);
  if (!split) return std::nullopt;
  try {
    const Handle(IntTools_Context) context = new IntTools_Context;
    std::vector<TopoDS_Face> kept;
    for (const TopoDS_Face& face : *split) {
      gp_Pnt point;
      gp_Pnt2d uv;
      if (BOPTools_AlgoTools3D::PointInFace(face, point, uv, context) != 0) return std::nullopt;
      if (keep(point)) kept.push_back(face);
    }
    return kept;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace airshape::geometry
