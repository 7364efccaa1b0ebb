#include "airshape/geometry/plane_region.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAPI_InterCurveCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IntRes2d_IntersectionPoint.hxx>
#include <IntRes2d_IntersectionSegment.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

namespace airshape::geometry {

PlaneCurve planeCurve(const gp_Pln& plane, const Handle(Geom_BSplineCurve) & curve) {
  const gp_Ax3& axes = plane.Position();
  const gp_Pnt origin = axes.Location();
  const gp_Vec x(axes.XDirection()), y(axes.YDirection());
  Handle(Geom_BSplineCurve) inPlane = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  if (inPlane->IsPeriodic()) inPlane->SetNotPeriodic();  // a closed curve, begun at its seam
  TColgp_Array1OfPnt2d images(1, inPlane->NbPoles());
  for (int i = 1; i <= inPlane->NbPoles(); ++i) {
    const gp_Vec offset(origin, inPlane->Pole(i));
    const gp_Pnt2d image(offset.Dot(x), offset.Dot(y));
    images.SetValue(i, image);
    inPlane->SetPole(i, origin.Translated(image.X() * x + image.Y() * y));
  }
  TColStd_Array1OfReal knots(1, inPlane->NbKnots());
  TColStd_Array1OfInteger multiplicities(1, inPlane->NbKnots());
  inPlane->Knots(knots);
  inPlane->Multiplicities(multiplicities);
  Handle(Geom2d_BSplineCurve) image;
  if (inPlane->IsRational()) {
    TColStd_Array1OfReal weights(1, inPlane->NbPoles());
    inPlane->Weights(weights);
    image = new Geom2d_BSplineCurve(images, weights, knots, multiplicities, inPlane->Degree());
  } else {
    image = new Geom2d_BSplineCurve(images, knots, multiplicities, inPlane->Degree());
  }
  return {inPlane, image};
}

namespace {

/// The piece of a curve between two of its parameters, as a B-spline of its own.
Handle(Geom_BSplineCurve) pieceOf(const Handle(Geom_BSplineCurve) & curve, double from, double to) {
  Handle(Geom_BSplineCurve) piece = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  if (from > piece->FirstParameter() || to < piece->LastParameter()) piece->Segment(from, to);
  return piece;
}

}  // namespace

Handle(Geom_BSplineCurve) edgeCurve(const TopoDS_Edge& edge) {
  double first = 0.0, last = 0.0;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
  if (curve.IsNull()) return nullptr;
  Handle(Geom_BSplineCurve) spline = Handle(Geom_BSplineCurve)::DownCast(curve);
  spline = spline.IsNull() ? GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, first, last))
                           : pieceOf(spline, first, last);
  if (edge.Orientation() == TopAbs_REVERSED) spline->Reverse();
  return spline;
}

namespace {

/// Points along a loop, closely enough to stand for it in the tests of which side a point
/// lies on and of how it runs: each knot span's start and middle, at least sixteen to a curve (the
/// curves traced from skins have hundreds of short spans; sampling each more densely cost
/// two fifths of a device plate's time).
std::vector<gp_Pnt2d> polygonOf(const PlaneLoop& loop) {
  std::vector<gp_Pnt2d> points;
  for (const PlaneCurve& curve : loop) {
    const Geom2d_BSplineCurve& image = *curve.image;
    const int spans = image.NbKnots() - 1, perSpan = std::max(2, (16 + spans - 1) / spans);
    for (int k = 1; k <= spans; ++k) {
      const double a = image.Knot(k), b = image.Knot(k + 1);
      for (int i = 0; i < perSpan; ++i) points.push_back(image.Value(a + (b - a) * i / perSpan));
    }
  }
  return points;
}

/// Twice the signed area a polygon encloses (positive counterclockwise).
double doubleArea(const std::vector<gp_Pnt2d>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const gp_Pnt2d &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    sum += p.X() * q.Y() - q.X() * p.Y();
  }
  return sum;
}

/// Whether a point lies inside a region given by the polygons of its loops (even-odd rule).
bool insideOf(const std::vector<std::vector<gp_Pnt2d>>& polygons, const gp_Pnt2d& point) {
  bool inside = false;
  for (const std::vector<gp_Pnt2d>& polygon : polygons)
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const gp_Pnt2d &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
      if ((p.Y() > point.Y()) == (q.Y() > point.Y())) continue;
      const double x = p.X() + (point.Y() - p.Y()) * (q.X() - p.X()) / (q.Y() - p.Y());
      if (x > point.X()) inside = !inside;
    }
  return inside;
}

std::vector<std::vector<gp_Pnt2d>> polygonsOf(const PlaneRegion& region) {
  std::vector<std::vector<gp_Pnt2d>> polygons;
  for (const PlaneLoop& loop : region) polygons.push_back(polygonOf(loop));
  return polygons;
}

/// A place on a region's boundary: which loop, which of its curves, at which parameter.
struct Place {
  std::size_t loop = 0, curve = 0;
  double t = 0.0;
  bool operator<(const Place& other) const {
    return std::tie(loop, curve, t) < std::tie(other.loop, other.curve, other.t);
  }
};

/// Where the two boundaries cross: the place on each, and the point.
struct Crossing {
  Place onA, onB;
  gp_Pnt point;
};

/// Where the two boundaries run together: the stretch on each (one curve of each, between two
/// parameters), and whether they run opposite ways.
struct Overlap {
  Place fromA, toA, fromB, toB;
  bool opposite = false;
};

/// How the two boundaries meet: where they cross (the ends of where they run together too),
/// and where they run together.
struct Meetings {
  std::vector<Crossing> crossings;
  std::vector<Overlap> overlaps;

  /// Adds a crossing unless one lies there already (one found on two curves meeting at a joint).
  void add(const Crossing& crossing, double tolerance) {
    const bool known = std::any_of(crossings.begin(), crossings.end(), [&](const Crossing& other) {
      return other.point.Distance(crossing.point) <= tolerance;
    });
    if (!known) crossings.push_back(crossing);
  }
  bool near(const gp_Pnt& point, double tolerance) const {
    return std::any_of(crossings.begin(), crossings.end(),
                       [&](const Crossing& crossing) { return crossing.point.Distance(point) <= tolerance; });
  }
};

/// Overlaps of one pair of curves that follow each other with a little gap between them made
/// one: where two boundaries made separately agree within their tolerances only (a Boolean
/// result's edge along a skin's own edge), the curve intersection finds them apart, and the
/// stretch between would lie on neither side.
void mergeNeighbouringOverlaps(std::vector<Overlap>& overlaps, const PlaneRegion& a, const PlaneRegion& b) {
  const auto low = [](const Place& from, const Place& to) { return std::min(from.t, to.t); };
  const auto high = [](const Place& from, const Place& to) { return std::max(from.t, to.t); };
  std::sort(overlaps.begin(), overlaps.end(), [&](const Overlap& x, const Overlap& y) {
    return std::make_tuple(x.fromA.loop, x.fromA.curve, x.fromB.loop, x.fromB.curve, low(x.fromA, x.toA)) <
           std::make_tuple(y.fromA.loop, y.fromA.curve, y.fromB.loop, y.fromB.curve, low(y.fromA, y.toA));
  });
  std::vector<Overlap> merged;
  for (const Overlap& overlap : overlaps) {
    if (!merged.empty()) {
      Overlap& last = merged.back();
      const PlaneCurve& curveA = a[overlap.fromA.loop][overlap.fromA.curve];
      const PlaneCurve& curveB = b[overlap.fromB.loop][overlap.fromB.curve];
      const double rangeA = curveA.image->LastParameter() - curveA.image->FirstParameter();
      const double rangeB = curveB.image->LastParameter() - curveB.image->FirstParameter();
      const bool samePair = last.fromA.loop == overlap.fromA.loop && last.fromA.curve == overlap.fromA.curve &&
                            last.fromB.loop == overlap.fromB.loop && last.fromB.curve == overlap.fromB.curve &&
                            last.opposite == overlap.opposite;
      const double gapA = low(overlap.fromA, overlap.toA) - high(last.fromA, last.toA);
      const double gapB = std::max(low(overlap.fromB, overlap.toB) - high(last.fromB, last.toB),
                                   low(last.fromB, last.toB) - high(overlap.fromB, overlap.toB));
      if (samePair && gapA <= 1e-3 * rangeA && gapB <= 1e-3 * rangeB) {
        // The union of the two stretches on each curve.
        last.fromA.t = std::min(low(last.fromA, last.toA), low(overlap.fromA, overlap.toA));
        last.toA.t = std::max(high(last.fromA, last.toA), high(overlap.fromA, overlap.toA));
        const double fromB = std::min(low(last.fromB, last.toB), low(overlap.fromB, overlap.toB));
        const double toB = std::max(high(last.fromB, last.toB), high(overlap.fromB, overlap.toB));
        last.fromB.t = fromB, last.toB.t = toB;
        continue;
      }
    }
    merged.push_back(overlap);
  }
  overlaps = merged;
}

/// Every crossing and overlap of the two boundaries; nothing where they touch without crossing.
std::optional<Meetings> meetingsOf(const PlaneRegion& a, const PlaneRegion& b, double tolerance) {
  Meetings meetings;
  std::vector<Crossing> points;  // taken after the overlaps, whose ends they may repeat
  for (std::size_t la = 0; la < a.size(); ++la)
    for (std::size_t ca = 0; ca < a[la].size(); ++ca)
      for (std::size_t lb = 0; lb < b.size(); ++lb)
        for (std::size_t cb = 0; cb < b[lb].size(); ++cb) {
          const PlaneCurve &first = a[la][ca], &second = b[lb][cb];
          const Geom2dAPI_InterCurveCurve meeting(first.image, second.image, 0.1 * tolerance);
          for (int k = 1; k <= meeting.NbSegments(); ++k) {
            const IntRes2d_IntersectionSegment& segment = meeting.Intersector().Segment(k);
            if (!segment.HasFirstPoint() || !segment.HasLastPoint()) return std::nullopt;
            const IntRes2d_IntersectionPoint &start = segment.FirstPoint(), &end = segment.LastPoint();
            meetings.overlaps.push_back({{la, ca, start.ParamOnFirst()},
                                         {la, ca, end.ParamOnFirst()},
                                         {lb, cb, start.ParamOnSecond()},
                                         {lb, cb, end.ParamOnSecond()},
                                         segment.IsOpposite()});
            for (const IntRes2d_IntersectionPoint* point : {&start, &end})
              meetings.add({{la, ca, point->ParamOnFirst()},
                            {lb, cb, point->ParamOnSecond()},
                            first.curve->Value(point->ParamOnFirst())},
                           tolerance);
          }
          for (int i = 1; i <= meeting.NbPoints(); ++i) {
            const IntRes2d_IntersectionPoint& point = meeting.Intersector().Point(i);
            points.push_back({{la, ca, point.ParamOnFirst()},
                              {lb, cb, point.ParamOnSecond()},
                              first.curve->Value(point.ParamOnFirst())});
          }
        }
  mergeNeighbouringOverlaps(meetings.overlaps, a, b);
  for (const Crossing& crossing : points) {
    if (meetings.near(crossing.point, tolerance)) continue;
    gp_Pnt2d at;
    gp_Vec2d da, db;
    a[crossing.onA.loop][crossing.onA.curve].image->D1(crossing.onA.t, at, da);
    b[crossing.onB.loop][crossing.onB.curve].image->D1(crossing.onB.t, at, db);
    if (std::abs(da.Crossed(db)) <= 1e-6 * da.Magnitude() * db.Magnitude()) return std::nullopt;  // a touch
    meetings.add(crossing, tolerance);
  }
  return meetings;
}

/// The overlap a run of a (`onA`) or b lies in, by its middle; nothing when it lies in none.
std::optional<Overlap> overlapHolding(const std::vector<Overlap>& overlaps, const Place& middle, bool onA) {
  for (const Overlap& overlap : overlaps) {
    const Place &from = onA ? overlap.fromA : overlap.fromB, &to = onA ? overlap.toA : overlap.toB;
    if (from.loop == middle.loop && from.curve == middle.curve && middle.t > std::min(from.t, to.t) &&
        middle.t < std::max(from.t, to.t))
      return overlap;
  }
  return std::nullopt;
}

/// A run along one loop of a boundary from one crossing to the next (or, for a loop no
/// crossing meets, the whole loop): its curves' pieces and the crossings at its ends.
struct Run {
  std::vector<Handle(Geom_BSplineCurve)> pieces;
  std::optional<std::size_t> from, to;  ///< crossing indices; none for a whole loop
  gp_Pnt2d middle;                      ///< a point of the run away from its ends
  Place middlePlace;                    ///< where that point lies on its loop
};

/// The runs of a region's boundary between the crossings (`onA`: their places on a, else b).
std::vector<Run> runsOf(const PlaneRegion& region, const std::vector<Crossing>& crossings, bool onA, double tolerance) {
  std::vector<Run> runs;
  for (std::size_t l = 0; l < region.size(); ++l) {
    const PlaneLoop& loop = region[l];
    std::vector<std::pair<Place, std::size_t>> marks;
    for (std::size_t i = 0; i < crossings.size(); ++i) {
      const Place& place = onA ? crossings[i].onA : crossings[i].onB;
      if (place.loop == l) marks.emplace_back(place, i);
    }
    std::sort(marks.begin(), marks.end());
    if (marks.empty()) {
      Run whole;
      for (const PlaneCurve& curve : loop) whole.pieces.push_back(curve.curve);
      const PlaneCurve& first = loop.front();
      const double t = 0.5 * (first.image->FirstParameter() + first.image->LastParameter());
      whole.middle = first.image->Value(t);
      whole.middlePlace = {l, 0, t};
      runs.push_back(whole);
      continue;
    }
    // From each mark along the loop (round its end) to the next.
    for (std::size_t m = 0; m < marks.size(); ++m) {
      const auto& [start, startIndex] = marks[m];
      const auto& [end, endIndex] = marks[(m + 1) % marks.size()];
      Run run;
      run.from = startIndex;
      run.to = endIndex;
      double longest = -1.0;
      std::size_t curve = start.curve;
      double t = start.t;
      for (std::size_t step = 0; step <= loop.size(); ++step) {
        const PlaneCurve& here = loop[curve];
        // The run ends on the end mark's curve, unless that is where it starts and the end
        // lies behind the start (the run goes round the loop first).
        const bool last = curve == end.curve && (step > 0 || end.t > t);
        const double stop = last ? end.t : here.curve->LastParameter();
        const gp_Pnt a = here.curve->Value(t), b = here.curve->Value(stop);
        if (stop - t > 1e-12 * (here.curve->LastParameter() - here.curve->FirstParameter()) &&
            a.Distance(b) > tolerance) {
          run.pieces.push_back(pieceOf(here.curve, t, stop));
          if (a.Distance(b) > longest) {
            longest = a.Distance(b);
            run.middle = here.image->Value(0.5 * (t + stop));
            run.middlePlace = {l, curve, 0.5 * (t + stop)};
          }
        }
        if (last) break;
        curve = (curve + 1) % loop.size();
        t = loop[curve].curve->FirstParameter();
      }
      if (!run.pieces.empty()) runs.push_back(run);
    }
  }
  return runs;
}

/// The face of the plane a closed chain of curve pieces bounds, the pieces joined by shared
/// vertices; nothing when OCCT cannot make it.
std::optional<TopoDS_Face> faceOf(const gp_Pln& plane, const std::vector<Handle(Geom_BSplineCurve)>& pieces,
                                  double tolerance) {
  std::vector<TopoDS_Vertex> vertices;
  BRep_Builder builder;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const gp_Pnt end = pieces[i]->EndPoint(), next = pieces[(i + 1) % pieces.size()]->StartPoint();
    TopoDS_Vertex vertex;
    builder.MakeVertex(vertex, gp_Pnt(0.5 * (end.XYZ() + next.XYZ())),
                       std::max(2.0 * tolerance, 0.6 * end.Distance(next)));
    vertices.push_back(vertex);
  }
  BRepBuilderAPI_MakeWire wire;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const TopoDS_Vertex& from = vertices[(i + pieces.size() - 1) % pieces.size()];
    BRepBuilderAPI_MakeEdge edge(pieces[i], from, vertices[i], pieces[i]->FirstParameter(), pieces[i]->LastParameter());
    if (!edge.IsDone()) return std::nullopt;
    wire.Add(edge.Edge());
    if (!wire.IsDone()) return std::nullopt;
  }
  // The chain runs counterclockwise about the plane's normal, so the face is the inside of
  // its wire as it is (no classification to find which side).
  BRepBuilderAPI_MakeFace face(plane, wire.Wire(), false);
  if (!face.IsDone()) return std::nullopt;
  return face.Face();
}

}  // namespace

std::optional<PlaneRegion> regionOf(const gp_Pln& plane, const TopoDS_Face& face) {
  int wires = 0;
  for (TopExp_Explorer wire(face, TopAbs_WIRE); wire.More(); wire.Next()) ++wires;
  if (wires != 1) return std::nullopt;
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (BRepTools_WireExplorer edge(BRepTools::OuterWire(face), face); edge.More(); edge.Next()) {
    curves.push_back(edgeCurve(edge.Current()));
    if (curves.back().IsNull()) return std::nullopt;
  }
  return regionInside(plane, curves);
}

std::optional<PlaneRegion> regionInside(const gp_Pln& plane, const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  PlaneLoop loop;
  for (const Handle(Geom_BSplineCurve) & curve : curves) loop.push_back(planeCurve(plane, curve));
  if (loop.empty()) return std::nullopt;
  if (doubleArea(polygonOf(loop)) < 0.0) {  // the region lies on its left when it runs the other way
    std::reverse(loop.begin(), loop.end());
    for (PlaneCurve& curve : loop) {
      curve.curve->Reverse();
      curve.image->Reverse();
    }
  }
  return PlaneRegion{loop};
}

std::optional<std::vector<TopoDS_Face>> commonOf(const gp_Pln& plane, const PlaneRegion& a, const PlaneRegion& b,
                                                 double tolerance) {
  const std::optional<Meetings> meetings = meetingsOf(a, b, tolerance);
  if (!meetings) return std::nullopt;
  // The common's boundary: the runs of each boundary inside the other region. Each leaves a
  // crossing where the run before it (of either boundary) arrives: the common lies on the
  // left of both. Where the boundaries run together, the common's boundary follows them once
  // (a's run) if both regions lie on the same side, else not at all.
  std::vector<Run> kept;
  const auto keep = [&](const PlaneRegion& region, const PlaneRegion& other, bool onA) {
    const std::vector<std::vector<gp_Pnt2d>> polygons = polygonsOf(other);
    for (const Run& run : runsOf(region, meetings->crossings, onA, tolerance)) {
      if (const auto overlap = overlapHolding(meetings->overlaps, run.middlePlace, onA)) {
        if (onA && !overlap->opposite) kept.push_back(run);
      } else if (insideOf(polygons, run.middle)) {
        kept.push_back(run);
      }
    }
  };
  keep(a, b, true);
  keep(b, a, false);
  std::map<std::size_t, std::size_t> leaving;  // crossing -> the kept run leaving it
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (kept[i].from && !leaving.emplace(*kept[i].from, i).second) return std::nullopt;
  std::vector<bool> used(kept.size(), false);
  std::vector<TopoDS_Face> faces;
  for (std::size_t first = 0; first < kept.size(); ++first) {
    if (used[first]) continue;
    std::vector<Handle(Geom_BSplineCurve)> chain;
    std::size_t run = first;
    for (std::size_t step = 0; step <= kept.size(); ++step) {
      used[run] = true;
      chain.insert(chain.end(), kept[run].pieces.begin(), kept[run].pieces.end());
      if (!kept[run].to) break;  // a whole loop
      const auto next = leaving.find(*kept[run].to);
      if (next == leaving.end()) return std::nullopt;
      run = next->second;
      if (run == first) break;
      if (used[run]) return std::nullopt;
    }
    if (kept[run].to && run != first) return std::nullopt;
    std::vector<gp_Pnt2d> polygon;
    for (const Handle(Geom_BSplineCurve) & piece : chain) {
      const PlaneCurve image = planeCurve(plane, piece);
      const std::vector<gp_Pnt2d> points = polygonOf({image});
      polygon.insert(polygon.end(), points.begin(), points.end());
    }
    if (doubleArea(polygon) <= 0.0) return std::nullopt;  // a hole, or nothing
    const std::optional<TopoDS_Face> face = faceOf(plane, chain, tolerance);
    if (!face) return std::nullopt;
    faces.push_back(*face);
  }
  return faces;
}

}  // namespace airshape::geometry
