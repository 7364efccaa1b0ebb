#include "skin_split.h"

#include <algorithm>
#include <cmath>

#include <BOPAlgo_BuilderFace.hxx>
#include <BOPTools_AlgoTools.hxx>
#include <BOPTools_AlgoTools3D.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2dAPI_ProjectPointOnCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <IntTools_Context.hxx>
#include <NCollection_DataMap.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt2d.hxx>

#include "bspline_patch.h"

namespace airshape::structure {

namespace {

/// Where a line of a side meets the skin: on which patch, at which of its parameters.
struct Hit {
  std::size_t patch = 0;
  PatchPoint at;
};

/// The lines of one side of the loop and where they meet the skin's patches.
class Side {
 public:
  Side(const std::vector<Patch>& patches, const gp_Pnt& from, const gp_Pnt& to, const gp_Vec& fromDirection,
       const gp_Vec& toDirection)
      : patches_(patches), from_(from), to_(to), fromDirection_(fromDirection), toDirection_(toDirection) {}

  /// Where the line at `lambda` meets the patch, from the guess `near`; nothing where it meets
  /// it outside the patch's bounds.
  std::optional<Hit> on(std::size_t patch, double lambda, const PatchPoint& near) const {
    PatchPoint point = near;
    if (!meetLine(patches_[patch], base(lambda), direction(lambda), point)) return std::nullopt;
    point.t = lambda;
    return Hit{patch, point};
  }

  /// Every patch the line at `lambda` meets, each found from a grid of starting guesses.
  std::vector<Hit> search(double lambda) const {
    constexpr int kGuesses = 6;
    std::vector<Hit> hits;
    for (std::size_t k = 0; k < patches_.size(); ++k) {
      const Patch& patch = patches_[k];
      for (int i = 0; i < kGuesses * kGuesses; ++i) {
        PatchPoint guess;
        guess.u = patch.u0 + (patch.u1 - patch.u0) * (0.5 + i / kGuesses) / kGuesses;
        guess.v = patch.v0 + (patch.v1 - patch.v0) * (0.5 + i % kGuesses) / kGuesses;
        if (const auto hit = on(k, lambda, guess)) {
          hits.push_back(*hit);
          break;
        }
      }
    }
    return hits;
  }

  const Patch& patch(std::size_t k) const { return patches_[k]; }

 private:
  gp_Pnt base(double lambda) const { return gp_Pnt(from_.XYZ() + lambda * (to_.XYZ() - from_.XYZ())); }
  gp_Vec direction(double lambda) const { return fromDirection_ + lambda * (toDirection_ - fromDirection_); }

  const std::vector<Patch>& patches_;
  gp_Pnt from_, to_;
  gp_Vec fromDirection_, toDirection_;
};

/// A part of a side's crossing on one patch: its points by the side's parameter.
struct Piece {
  std::size_t patch = 0;
  std::vector<PatchPoint> points;
};

/// Moves a point lying within the tolerance of a patch's bound onto it, so that a curve ending
/// there ends on the face's edge.
PatchPoint ontoBound(const Patch& patch, PatchPoint point, double tolerance) {
  auto snap = [&](double& parameter, double low, double high) {
    for (const double bound : {low, high}) {
      if (std::abs(parameter - bound) > 1e-4 * (high - low)) continue;
      const double kept = parameter;
      parameter = bound;
      if (patch.surface->Value(point.u, point.v).Distance(point.point) > tolerance) parameter = kept;
    }
  };
  snap(point.u, patch.u0, patch.u1);
  snap(point.v, patch.v0, patch.v1);
  point.point = patch.surface->Value(point.u, point.v);
  return point;
}

/// Thrown where a line meets the skin at two points (a wing folding back over itself): the
/// direct split does not apply.
struct FoldedSkin {};

/// The one point where the line at `lambda` meets the skin, on the patch the crossing goes on
/// over towards `ahead`; nothing when it misses the skin. Throws FoldedSkin where it meets it at
/// two points.
std::optional<Hit> entry(const Side& side, double lambda, double ahead, double tolerance) {
  const std::vector<Hit> hits = side.search(lambda);
  if (hits.empty()) return std::nullopt;
  for (const Hit& hit : hits)
    if (hit.at.point.Distance(hits.front().at.point) > tolerance) throw FoldedSkin();
  for (const Hit& hit : hits)
    if (side.on(hit.patch, ahead, hit.at)) return Hit{hit.patch, ontoBound(side.patch(hit.patch), hit.at, tolerance)};
  return Hit{hits.front().patch, ontoBound(side.patch(hits.front().patch), hits.front().at, tolerance)};
}

/// The last point of the crossing on the piece's patch before the line at `beyond` (which
/// meets it outside the patch), by bisection, and the line's parameter just past it.
std::pair<PatchPoint, double> exitFrom(const Side& side, const Piece& piece, double beyond, double tolerance) {
  PatchPoint last = piece.points.back();
  for (int halving = 0; halving < 50; ++halving) {
    const double middle = 0.5 * (last.t + beyond);
    if (const auto hit = side.on(piece.patch, middle, last))
      last = hit->at;
    else
      beyond = middle;
  }
  return {ontoBound(side.patch(piece.patch), last, tolerance), beyond};
}

/// The first point of the crossing on the skin after the line at `outside` (which misses it),
/// by bisection towards `inside`, a hit of a later line.
Hit reentry(const Side& side, double outside, Hit inside, double tolerance) {
  for (int halving = 0; halving < 50; ++halving) {
    const double middle = 0.5 * (outside + inside.at.t);
    if (const auto hit = side.on(inside.patch, middle, inside.at))
      inside = *hit;
    else
      outside = middle;
  }
  inside.at = ontoBound(side.patch(inside.patch), inside.at, tolerance);
  return inside;
}

/// The side's crossing of the skin, piece by patch: sampled evenly, each change of patch found
/// by bisection. Where the side runs beyond the skin's edge (past its leading or trailing edge,
/// its root or tip), the region follows that edge, which the skin has already: no piece there.
std::optional<std::vector<Piece>> piecesOf(const Side& side, double tolerance) {
  constexpr int kSamples = 16;
  const double step = 1.0 / kSamples;
  std::vector<Piece> pieces;
  auto add = [&](Piece& piece, const PatchPoint& point) {
    piece.points.push_back(ontoBound(side.patch(piece.patch), point, tolerance));
  };
  auto begin = [&](const Hit& hit) {
    pieces.push_back({hit.patch, {}});
    add(pieces.back(), hit.at);
  };
  bool onSkin = false;
  double outside = 0.0;  // off the skin: the last line found to miss it
  if (const auto first = entry(side, 0.0, step, tolerance)) {
    begin(*first);
    onSkin = true;
  }
  for (int i = 1, steps = 0; i <= kSamples; ++i) {
    if (++steps > 256) return std::nullopt;
    const double lambda = static_cast<double>(i) / kSamples;
    if (!onSkin) {
      if (const auto hit = entry(side, lambda, std::min(1.0, lambda + step), tolerance)) {
        begin(reentry(side, outside, *hit, tolerance));
        if (hit->at.t > pieces.back().points.back().t) add(pieces.back(), hit->at);
        onSkin = true;
      } else {
        outside = lambda;
      }
      continue;
    }
    Piece& piece = pieces.back();
    if (const auto hit = side.on(piece.patch, lambda, piece.points.back())) {
      add(piece, hit->at);
      continue;
    }
    // The crossing left the patch between the last point and this line: onto a neighbouring
    // patch, or off the skin.
    const auto [last, off] = exitFrom(side, piece, lambda, tolerance);
    if (last.t > piece.points.back().t) add(piece, last);
    const auto next = entry(side, off, std::min(1.0, off + step), tolerance);
    if (next && next->patch != piece.patch) {
      begin(*next);
    } else {  // off the skin (or back on the same patch, which the next line takes up)
      onSkin = false;
      outside = off;
    }
    --i;  // this line again, from there
  }
  // A piece over a mere corner of a patch (the crossing passing through a vertex) is left out:
  // its neighbours meet within the vertices' tolerance.
  std::vector<Piece> kept;
  for (const Piece& piece : pieces)
    if (piece.points.back().t - piece.points.front().t > 1e-9) kept.push_back(piece);
  for (const Piece& piece : kept)
    if (piece.points.size() < 2) return std::nullopt;
  return kept;
}

/// The curve through a piece's points in its patch's parameters, by the side's parameter.
Handle(Geom2d_BSplineCurve) curveThrough(const Piece& piece) {
  const int n = static_cast<int>(piece.points.size());
  Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, n);
  Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, n);
  for (int i = 0; i < n; ++i) {
    const PatchPoint& point = piece.points[static_cast<std::size_t>(i)];
    points->SetValue(i + 1, gp_Pnt2d(point.u, point.v));
    parameters->SetValue(i + 1, point.t);
  }
  Geom2dAPI_Interpolate interpolation(points, parameters, false, 1e-15);
  interpolation.Perform();
  if (!interpolation.IsDone()) return nullptr;
  return interpolation.Curve();
}

/// Adds points halfway between two where the curve strays from the crossing by more than the
/// tolerance; true when it strays nowhere.
bool followsCrossing(const Side& side, Piece& piece, const Handle(Geom2d_BSplineCurve) & curve, double tolerance,
                     bool& failed) {
  const Patch& patch = side.patch(piece.patch);
  std::vector<PatchPoint> denser{piece.points.front()};
  bool close = true;
  for (std::size_t i = 1; i < piece.points.size(); ++i) {
    const double middle = 0.5 * (piece.points[i - 1].t + piece.points[i].t);
    const auto hit = side.on(piece.patch, middle, piece.points[i - 1]);
    if (!hit) {
      failed = true;
      return false;
    }
    const gp_Pnt2d uv = curve->Value(middle);
    if (patch.surface->Value(uv.X(), uv.Y()).Distance(hit->at.point) > tolerance) {
      close = false;
      denser.push_back(hit->at);
    }
    denser.push_back(piece.points[i]);
  }
  piece.points = denser;
  return close;
}

/// Whether a piece runs along one of its patch's bounds (a border of the region on an edge the
/// skin has already): no curve is needed there.
bool alongBound(const Patch& patch, const Piece& piece) {
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
    const Side side(patches, loop.points[k], loop.points[next], loop.directions[k], loop.directions[next]);
    auto pieces = piecesOf(side, tolerance);
    if (!pieces) return std::nullopt;
    for (Piece& piece : *pieces) {
      Handle(Geom2d_BSplineCurve) curve = curveThrough(piece);
      bool failed = false;
      for (int round = 0; curve && !followsCrossing(side, piece, curve, tolerance, failed); ++round) {
        if (failed || round == 8) return std::nullopt;
        curve = curveThrough(piece);
      }
      if (!curve) return std::nullopt;
      // Ends on a bound lie on it exactly, so that the curve splits the face there.
      const Patch& patch = patches[piece.patch];
      if (!alongBound(patch, piece))
        drawn.push_back({piece.patch, curve, ontoBound(patch, piece.points.front(), tolerance),
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
    TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(point).Vertex();
    BRep_Builder().UpdateVertex(vertex, tolerance_);
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
    if (!BRepLib::BuildCurve3d(made)) return std::nullopt;
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

/// The skin's faces and their patches; nothing when a face is not an untrimmed B-spline patch.
std::optional<std::pair<std::vector<TopoDS_Face>, std::vector<Patch>>> patchesOf(const TopoDS_Shape& skin) {
  std::vector<TopoDS_Face> faces;
  std::vector<Patch> patches;
  for (TopExp_Explorer face(skin, TopAbs_FACE); face.More(); face.Next()) {
    const auto patch = patchOf(TopoDS::Face(face.Current()));
    if (!patch) return std::nullopt;
    faces.push_back(TopoDS::Face(face.Current()));
    patches.push_back(*patch);
  }
  return std::make_pair(faces, patches);
}

}  // namespace

std::optional<std::vector<TopoDS_Face>> skinInsideLoop(const TopoDS_Shape& skin, const RuledLoop& loop,
                                                       double tolerance) {
  const auto patches = patchesOf(skin);
  if (!patches) return std::nullopt;
  std::optional<std::vector<Drawn>> drawn;
  try {
    drawn = crossingsOf(patches->second, loop, tolerance);
  } catch (const FoldedSkin&) {
    return std::nullopt;
  }
  if (!drawn) return std::nullopt;
  const auto split = splitFaces(patches->first, patches->second, *drawn, skin, tolerance);
  if (!split) return std::nullopt;
  const Handle(IntTools_Context) context = new IntTools_Context;
  BRepClass3d_SolidClassifier prism(loop.prism);
  std::vector<TopoDS_Face> inside;
  for (const TopoDS_Face& face : *split) {
    gp_Pnt point;
    gp_Pnt2d uv;
    if (BOPTools_AlgoTools3D::PointInFace(face, point, uv, context) != 0) return std::nullopt;
    prism.Perform(point, tolerance);
    if (prism.State() == TopAbs_IN) inside.push_back(face);
  }
  return inside;
}

}  // namespace airshape::structure
