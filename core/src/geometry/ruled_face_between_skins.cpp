#include "airshape/geometry/ruled_face_between_skins.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepLib.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>

#include "airshape/geometry/brep_building.h"

namespace airshape::geometry {

namespace {

/// A point of the ruled surface by its parameters: t across the lines, s along the line.
struct LinePoint {
  double t = 0, s = 0;
};

/// A part of a skin's crossing on one skin patch, in the surface's parameters: its points and
/// the curve through them, by t.
struct SkinRun {
  std::vector<LinePoint> points;
  Handle(Geom2d_BSplineCurve) curve;
};

/// The parameter along the line at t of a point on it.
double alongLine(const RuledLines& lines, double t, const gp_Pnt& point) {
  const gp_Vec direction = lines.direction(t);
  return gp_Vec(lines.base(t), point).Dot(direction) / direction.SquareMagnitude();
}

/// The curve through a run's points in the surface's parameters, by t.
Handle(Geom2d_BSplineCurve) curveThrough(const std::vector<LinePoint>& run) {
  std::vector<gp_Pnt2d> points;
  std::vector<double> parameters;
  for (const LinePoint& point : run) {
    points.emplace_back(point.t, point.s);
    parameters.push_back(point.t);
  }
  return geometry::curveThroughPoints(points, parameters);
}

/// The run of a crossing piece: the curve through its points, with points added halfway
/// between two where it strays from the piece's own curve by more than the tolerance.
std::optional<SkinRun> runOf(const geometry::CrossingPiece& piece, const geometry::Patch& patch,
                             const RuledLines& lines, double tolerance) {
  auto onPiece = [&](double t) {
    const gp_Pnt2d uv = piece.curve->Value(t);
    return LinePoint{t, alongLine(lines, t, patch.surface->Value(uv.X(), uv.Y()))};
  };
  SkinRun run;
  for (const geometry::PatchPoint& point : piece.points)
    run.points.push_back({point.t, alongLine(lines, point.t, point.point)});
  for (int round = 0; round < 8; ++round) {
    run.curve = curveThrough(run.points);
    if (run.curve.IsNull()) return std::nullopt;
    std::vector<LinePoint> denser{run.points.front()};
    for (std::size_t i = 1; i < run.points.size(); ++i) {
      const LinePoint middle = onPiece(0.5 * (run.points[i - 1].t + run.points[i].t));
      const double strays = std::abs(run.curve->Value(middle.t).Y() - middle.s) * lines.direction(middle.t).Magnitude();
      if (strays > tolerance) denser.push_back(middle);
      denser.push_back(run.points[i]);
    }
    if (denser.size() == run.points.size()) return run;
    run.points = denser;
  }
  return std::nullopt;
}

/// One skin's crossing, run by run from the line at t = 0 to the line at t = 1; nothing when
/// it leaves a gap.
std::optional<std::vector<SkinRun>> crossingOf(const TopoDS_Shape& skin, const RuledLines& lines, double tolerance) {
  const auto patches = geometry::skinPatches(skin);
  if (!patches) return std::nullopt;
  const auto pieces = geometry::ruledCrossing(patches->patches, lines, tolerance);
  if (!pieces || !geometry::coversAllLines(*pieces)) return std::nullopt;
  std::vector<SkinRun> runs;
  for (const geometry::CrossingPiece& piece : *pieces) {
    const auto run = runOf(piece, patches->patches[piece.patch], lines, tolerance);
    if (!run) return std::nullopt;
    runs.push_back(*run);
  }
  return runs;
}

/// The ruled surface as a bilinear B-spline patch: u is t, v is s, over [-reach, reach].
Handle(Geom_BSplineSurface) surfaceOf(const RuledLines& lines, double reach) {
  TColgp_Array2OfPnt poles(1, 2, 1, 2);
  for (int row = 1; row <= 2; ++row)
    for (int column = 1; column <= 2; ++column) {
      const gp_Pnt& base = row == 1 ? lines.from : lines.to;
      const gp_Vec& direction = row == 1 ? lines.fromDirection : lines.toDirection;
      poles.SetValue(row, column, base.Translated((column == 1 ? -reach : reach) * direction));
    }
  TColStd_Array1OfReal uKnots(1, 2), vKnots(1, 2);
  TColStd_Array1OfInteger multiplicities(1, 2);
  uKnots(1) = 0.0, uKnots(2) = 1.0, vKnots(1) = -reach, vKnots(2) = reach;
  multiplicities(1) = multiplicities(2) = 2;
  return new Geom_BSplineSurface(poles, uKnots, vKnots, multiplicities, multiplicities, 1, 1);
}

/// The edge on the surface along a curve of its parameters between two vertices.
std::optional<TopoDS_Edge> edgeOn(const Handle(Geom_Surface) & surface, const Handle(Geom2d_Curve) & curve,
                                  const TopoDS_Vertex& from, const TopoDS_Vertex& to, double first, double last) {
  BRepBuilderAPI_MakeEdge edge(curve, surface, from, to, first, last);
  if (!edge.IsDone()) return std::nullopt;
  TopoDS_Edge made = edge.Edge();
  if (!BRepLib::BuildCurve3d(made)) return std::nullopt;
  return made;
}

/// The edges along a skin's crossing, from vertex `first` to vertex `last`, in order of t.
std::optional<std::vector<TopoDS_Edge>> crossingEdges(const Handle(Geom_Surface) & surface,
                                                      const std::vector<SkinRun>& runs, const TopoDS_Vertex& first,
                                                      const TopoDS_Vertex& last, double tolerance) {
  std::vector<TopoDS_Edge> edges;
  TopoDS_Vertex from = first;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const LinePoint& end = runs[k].points.back();
    const TopoDS_Vertex to =
        k + 1 == runs.size() ? last : geometry::vertexWithin(surface->Value(end.t, end.s), tolerance);
    const auto edge = edgeOn(surface, runs[k].curve, from, to, runs[k].points.front().t, end.t);
    if (!edge) return std::nullopt;
    edges.push_back(*edge);
    from = to;
  }
  return edges;
}

/// The straight edge along the line at t from the point at `fromS` (vertex `from`) to the point
/// at `toS`.
std::optional<TopoDS_Edge> alongLineEdge(const Handle(Geom_Surface) & surface, double t, const TopoDS_Vertex& from,
                                         double fromS, const TopoDS_Vertex& to, double toS) {
  const Handle(Geom2d_Line) line = new Geom2d_Line(gp_Pnt2d(t, 0.0), gp_Dir2d(0.0, 1.0));
  if (fromS < toS) return edgeOn(surface, line, from, to, fromS, toS);
  const auto reversed = edgeOn(surface, line, to, from, toS, fromS);
  if (!reversed) return std::nullopt;
  return TopoDS::Edge(reversed->Reversed());
}

/// The face of the ruled surface between two runs of its points, each from the line at t = 0 to
/// the line at t = 1, and those lines; throws OCCT's failures.
std::optional<TopoDS_Face> faceBetween(const std::optional<std::vector<SkinRun>>& upper,
                                       const std::optional<std::vector<SkinRun>>& lower, const RuledLines& lines,
                                       double tolerance) {
  if (!upper || !lower) return std::nullopt;
  double reach = 1.0;
  for (const auto* runs : {&*upper, &*lower})
    for (const SkinRun& run : *runs)
      for (const LinePoint& point : run.points) reach = std::max(reach, 2.0 * std::abs(point.s) + 1.0);
  const Handle(Geom_BSplineSurface) surface = surfaceOf(lines, reach);

  const double vertexTolerance = 10.0 * tolerance;
  const LinePoint lowerStart = lower->front().points.front(), lowerEnd = lower->back().points.back();
  const LinePoint upperStart = upper->front().points.front(), upperEnd = upper->back().points.back();
  auto vertexOf = [&](const LinePoint& p) { return geometry::vertexWithin(surface->Value(p.t, p.s), vertexTolerance); };
  const TopoDS_Vertex lowerFirst = vertexOf(lowerStart), lowerLast = vertexOf(lowerEnd);
  const TopoDS_Vertex upperFirst = vertexOf(upperStart), upperLast = vertexOf(upperEnd);
  const auto lowerEdges = crossingEdges(surface, *lower, lowerFirst, lowerLast, vertexTolerance);
  const auto upperEdges = crossingEdges(surface, *upper, upperFirst, upperLast, vertexTolerance);
  const auto endEdge = alongLineEdge(surface, 1.0, lowerLast, lowerEnd.s, upperLast, upperEnd.s);
  const auto startEdge = alongLineEdge(surface, 0.0, upperFirst, upperStart.s, lowerFirst, lowerStart.s);
  if (!lowerEdges || !upperEdges || !endEdge || !startEdge) return std::nullopt;

  // Around the face: along the lower skin, up the last line, back along the upper skin, down
  // the first line.
  BRepBuilderAPI_MakeWire wire;
  for (const TopoDS_Edge& edge : *lowerEdges) wire.Add(edge);
  wire.Add(*endEdge);
  for (auto edge = upperEdges->rbegin(); edge != upperEdges->rend(); ++edge) wire.Add(TopoDS::Edge(edge->Reversed()));
  wire.Add(*startEdge);
  if (!wire.IsDone()) return std::nullopt;
  BRepBuilderAPI_MakeFace face(surface, wire.Wire(), true);
  if (!face.IsDone() || !BRepCheck_Analyzer(face.Face()).IsValid()) return std::nullopt;
  return face.Face();
}

/// The section (ruledSectionBetweenSkins), throwing FoldedSkin or OCCT's failures where the
/// direct way does not apply.
std::optional<TopoDS_Face> sectionOf(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                     const RuledLines& lines, double tolerance) {
  return faceBetween(crossingOf(upperSkin, lines, tolerance), crossingOf(lowerSkin, lines, tolerance), lines,
                     tolerance);
}

/// The base line s = 0 of the ruled surface as a run.
std::vector<SkinRun> baseLine() {
  SkinRun run;
  run.points = {{0.0, 0.0}, {1.0, 0.0}};
  run.curve = curveThrough(run.points);
  return {run};
}

}  // namespace

std::optional<TopoDS_Face> ruledFaceOutToSkin(const TopoDS_Shape& skin, const RuledLines& lines, double tolerance) {
  try {
    return faceBetween(crossingOf(skin, lines, tolerance), baseLine(), lines, tolerance);
  } catch (const geometry::FoldedSkin&) {
    return std::nullopt;
  } catch (const Standard_Failure&) {  // a curve or face OCCT cannot make: the Boolean way then
    return std::nullopt;
  }
}

std::optional<TopoDS_Face> ruledSectionBetweenSkins(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                                    const RuledLines& lines, double tolerance) {
  try {
    return sectionOf(upperSkin, lowerSkin, lines, tolerance);
  } catch (const geometry::FoldedSkin&) {
    return std::nullopt;
  } catch (const Standard_Failure&) {  // a curve or face OCCT cannot make: the Boolean way then
    return std::nullopt;
  }
}

}  // namespace airshape::geometry
