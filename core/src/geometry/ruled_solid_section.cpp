#include "airshape/geometry/ruled_solid_section.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/geometry/curve_fit.h"

namespace airshape::geometry {

namespace {

constexpr int kSamples = 64;

/// The points of [a, b] where f changes sign: sampled, then bisected.
template <class Function>
std::vector<double> rootsOf(const Function& f, double a, double b) {
  std::vector<double> roots;
  double previous = a, fPrevious = f(a);
  if (fPrevious == 0.0) roots.push_back(a);
  for (int i = 1; i <= kSamples; ++i) {
    const double x = a + (b - a) * i / kSamples, fx = f(x);
    if (fx == 0.0) {
      roots.push_back(x);
    } else if (fPrevious != 0.0 && (fPrevious < 0.0) != (fx < 0.0)) {
      double low = previous, high = x;
      for (int step = 0; step < 100 && high - low > 1e-15 * (b - a); ++step) {
        const double middle = 0.5 * (low + high);
        ((f(low) < 0.0) == (f(middle) < 0.0) ? low : high) = middle;
      }
      roots.push_back(0.5 * (low + high));
    }
    previous = x, fPrevious = fx;
  }
  return roots;
}

/// A piece run so that the solid lies on its left (seen from the plane's normal): `inwards`
/// is a direction into the solid at its point `at` with the derivative `along`.
void turnInwards(Handle(Geom_BSplineCurve) & piece, const gp_Pln& plane, const gp_Vec& along, const gp_Vec& inwards) {
  if (gp_Vec(plane.Axis().Direction()).Crossed(along).Dot(inwards) < 0.0) piece->Reverse();
}

/// The face's outward normal from its surface's normal.
gp_Vec outwards(const TopoDS_Face& face, const gp_Vec& surfaceNormal) {
  return face.Orientation() == TopAbs_REVERSED ? surfaceNormal.Reversed() : surfaceNormal;
}

/// Where the plane crosses a planar face: the pieces of the planes' common line inside the
/// face, between its crossings with the face's edges taken in pairs. False where the planes
/// are one.
bool planarPieces(const TopoDS_Face& face, const gp_Pln& facePlane, const gp_Pln& plane, double tolerance,
                  std::vector<Handle(Geom_BSplineCurve)>& pieces) {
  const gp_Vec normal(plane.Axis().Direction());
  const gp_Vec line = normal.Crossed(gp_Vec(facePlane.Axis().Direction()));
  if (line.Magnitude() < 1e-12) return plane.Distance(facePlane.Location()) > tolerance;
  const auto side = [&](const gp_Pnt& p) { return gp_Vec(plane.Location(), p).Dot(normal); };
  std::vector<gp_Pnt> points;
  for (TopExp_Explorer explorer(face, TopAbs_EDGE); explorer.More(); explorer.Next()) {
    double first = 0.0, last = 0.0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(explorer.Current()), first, last);
    if (curve.IsNull()) return false;
    for (const double t : rootsOf([&](double x) { return side(curve->Value(x)); }, first, last)) {
      const gp_Pnt point = curve->Value(t);
      if (std::none_of(points.begin(), points.end(), [&](const gp_Pnt& p) { return p.Distance(point) <= tolerance; }))
        points.push_back(point);
    }
  }
  if (points.size() % 2 != 0) return false;
  std::sort(points.begin(), points.end(),
            [&](const gp_Pnt& a, const gp_Pnt& b) { return gp_Vec(a.XYZ()).Dot(line) < gp_Vec(b.XYZ()).Dot(line); });
  const gp_Vec inwards = outwards(face, gp_Vec(facePlane.Axis().Direction())).Reversed();
  for (std::size_t i = 0; i + 1 < points.size(); i += 2) {
    Handle(Geom_BSplineCurve) piece = straightCurve(points[i], points[i + 1]);
    turnInwards(piece, plane, gp_Vec(points[i], points[i + 1]), inwards);
    pieces.push_back(piece);
  }
  return true;
}

/// A ruled B-spline face: its rulings run from A(w) to B(w), w along the face.
class RuledFace {
 public:
  RuledFace(const Handle(Geom_BSplineSurface) & surface, bool rulingsAlongV, double u0, double u1, double v0, double v1)
      : surface_(surface), alongV_(rulingsAlongV), u0_(u0), u1_(u1), v0_(v0), v1_(v1) {}

  double first() const { return alongV_ ? u0_ : v0_; }
  double last() const { return alongV_ ? u1_ : v1_; }

  /// The ruling's ends at w and their derivatives along w.
  void ruling(double w, gp_Pnt& a, gp_Pnt& b, gp_Vec& da, gp_Vec& db) const {
    gp_Vec ignored;
    if (alongV_) {
      surface_->D1(w, v0_, a, da, ignored);
      surface_->D1(w, v1_, b, db, ignored);
    } else {
      surface_->D1(u0_, w, a, ignored, da);
      surface_->D1(u1_, w, b, ignored, db);
    }
  }

  /// The surface's normal at w, a share s along the ruling.
  gp_Vec normal(double w, double s) const {
    gp_Pnt point;
    gp_Vec du, dv;
    if (alongV_)
      surface_->D1(w, v0_ + s * (v1_ - v0_), point, du, dv);
    else
      surface_->D1(u0_ + s * (u1_ - u0_), w, point, du, dv);
    return du.Crossed(dv);
  }

 private:
  Handle(Geom_BSplineSurface) surface_;
  bool alongV_;
  double u0_, u1_, v0_, v1_;
};

/// Where the plane crosses a ruled face: for each ruling, the share s along it where it meets
/// the plane; pieces where 0 <= s <= 1 (a ruling running along the plane cannot hold one: s
/// is infinite there). False where a piece cannot be fitted.
bool ruledPieces(const TopoDS_Face& face, const RuledFace& ruled, const gp_Pln& plane, double tolerance,
                 std::vector<Handle(Geom_BSplineCurve)>& pieces) {
  const gp_Vec normal(plane.Axis().Direction());
  const double level = gp_Vec(plane.Location().XYZ()).Dot(normal);
  const auto share = [&](double w) {
    gp_Pnt a, b;
    gp_Vec da, db;
    ruled.ruling(w, a, b, da, db);
    return (level - gp_Vec(a.XYZ()).Dot(normal)) / gp_Vec(a, b).Dot(normal);
  };
  // Where a ruling runs along the plane the share jumps from one infinity to the other: the
  // face is taken in stretches between such rulings, on each of which the share is smooth.
  const auto across = [&](double w) {
    gp_Pnt a, b;
    gp_Vec da, db;
    ruled.ruling(w, a, b, da, db);
    return gp_Vec(a, b).Dot(normal);
  };
  const double w0 = ruled.first(), w1 = ruled.last(), slack = 1e-9 * (w1 - w0);
  std::vector<double> breaks{w0};
  for (const double w : rootsOf(across, w0, w1))
    if (w - breaks.back() > slack && w1 - w > slack) breaks.push_back(w);
  breaks.push_back(w1);
  // The stretches of w where the plane meets the ruling between its ends.
  std::vector<double> marks;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double from = breaks[k] + (k > 0 ? slack : 0.0), to = breaks[k + 1] - (k + 2 < breaks.size() ? slack : 0.0);
    marks.push_back(from);
    for (const double end : {0.0, 1.0}) {
      const std::vector<double> roots = rootsOf([&](double w) { return share(w) - end; }, from, to);
      marks.insert(marks.end(), roots.begin(), roots.end());
    }
    marks.push_back(to);
  }
  std::sort(marks.begin(), marks.end());
  const CurveSampler sample = [&](double w, const CurveSample&, const CurveSample&) {
    gp_Pnt a, b;
    gp_Vec da, db;
    ruled.ruling(w, a, b, da, db);
    const gp_Vec ab(a, b), dab = db - da;
    const double down = ab.Dot(normal), s = (level - gp_Vec(a.XYZ()).Dot(normal)) / down;
    const double ds =
        (-da.Dot(normal) * down - (level - gp_Vec(a.XYZ()).Dot(normal)) * dab.Dot(normal)) / (down * down);
    return std::optional<CurveSample>(
        CurveSample{w, a.Translated(s * ab), da + ds * ab + s * dab, gp_Pnt2d(w, std::clamp(s, 0.0, 1.0))});
  };
  for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
    const double a = marks[i], b = marks[i + 1];
    if (b - a <= 1e-12 * (w1 - w0)) continue;
    const double s = share(0.5 * (a + b));
    if (!(s >= 0.0 && s <= 1.0)) continue;  // also where the share is no number (a ruling in the plane)
    if (std::any_of(breaks.begin() + 1, breaks.end() - 1, [&](double w) { return w > a && w < b; })) continue;
    const std::optional<CurveSample> first = sample(a, {}, {}), last = sample(b, {}, {});
    if (first->point.Distance(last->point) <= tolerance) continue;
    Handle(Geom_BSplineCurve) piece = fittedCurve(sample, *first, *last, tolerance);
    if (piece.IsNull()) return false;
    const std::optional<CurveSample> middle = sample(0.5 * (a + b), {}, {});
    turnInwards(piece, plane, middle->tangent, outwards(face, ruled.normal(0.5 * (a + b), s)).Reversed());
    pieces.push_back(piece);
  }
  return true;
}

/// The pieces where the plane crosses one face; false where the face is of a kind not handled.
bool facePieces(const TopoDS_Face& face, const gp_Pln& plane, double tolerance,
                std::vector<Handle(Geom_BSplineCurve)>& pieces) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (const Handle(Geom_Plane) facePlane = Handle(Geom_Plane)::DownCast(surface))
    return planarPieces(face, facePlane->Pln(), plane, tolerance, pieces);
  const Handle(Geom_BSplineSurface) spline = Handle(Geom_BSplineSurface)::DownCast(surface);
  if (spline.IsNull()) return false;
  double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  if (spline->VDegree() == 1 && spline->NbVPoles() == 2)
    return ruledPieces(face, RuledFace(spline, true, u0, u1, v0, v1), plane, tolerance, pieces);
  if (spline->UDegree() == 1 && spline->NbUPoles() == 2)
    return ruledPieces(face, RuledFace(spline, false, u0, u1, v0, v1), plane, tolerance, pieces);
  return false;
}

/// The pieces joined end to end into closed loops; nothing when they do not close.
std::optional<PlaneRegion> loopsOf(const gp_Pln& plane, std::vector<Handle(Geom_BSplineCurve)> pieces,
                                   double tolerance) {
  const double gap = 1e3 * tolerance;  // the ends of neighbouring faces' pieces, found apart
  PlaneRegion region;
  std::vector<bool> used(pieces.size(), false);
  for (std::size_t first = 0; first < pieces.size(); ++first) {
    if (used[first]) continue;
    used[first] = true;
    PlaneLoop loop{planeCurve(plane, pieces[first])};
    while (loop.back().curve->EndPoint().Distance(loop.front().curve->StartPoint()) > gap) {
      const gp_Pnt end = loop.back().curve->EndPoint();
      std::size_t next = pieces.size();
      for (std::size_t i = 0; i < pieces.size(); ++i)
        if (!used[i] && pieces[i]->StartPoint().Distance(end) <= gap) next = i;
      if (next == pieces.size()) return std::nullopt;
      used[next] = true;
      loop.push_back(planeCurve(plane, pieces[next]));
    }
    region.push_back(loop);
  }
  return region;
}

}  // namespace

std::optional<PlaneRegion> ruledSolidSection(const TopoDS_Shape& solid, const gp_Pln& plane, double tolerance) {
  std::vector<Handle(Geom_BSplineCurve)> pieces;
  for (TopExp_Explorer face(solid, TopAbs_FACE); face.More(); face.Next())
    if (!facePieces(TopoDS::Face(face.Current()), plane, tolerance, pieces)) return std::nullopt;
  if (pieces.empty()) return PlaneRegion{};
  return loopsOf(plane, pieces, tolerance);
}

}  // namespace airshape::geometry
