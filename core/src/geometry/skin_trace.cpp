#include "airshape/geometry/skin_trace.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Mat.hxx>
#include <gp_Vec2d.hxx>

#include "airshape/geometry/bspline_patch.h"
#include "airshape/geometry/curve_fit.h"

namespace airshape::geometry {

double CrossingLines::lineThrough(const gp_Pnt& point) const {
  const gp_Vec up = across.Normalized();
  const gp_Vec level = along - along.Dot(up) * up;  // along, with its part along the lines taken out
  return gp_Vec(origin, point).Dot(level) / level.SquareMagnitude();
}

namespace {

/// Signed distance from the plane.
double side(const CrossingLines& lines, const gp_Vec& normal, const gp_Pnt& point) {
  return gp_Vec(lines.origin, point).Dot(normal);
}

/// The range of the lines (their t) a trace looks at: between its ends where they are lines of
/// the family, everywhere where an end is left open or lies on a border.
struct LineWindow {
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
};

/// Whether the plane can cross the patch within the window at all: its poles span the plane
/// and the lines through them meet the window (the patch lies in their convex hull, and the
/// line's parameter t is an affine function of the point).
bool poleHullCrossesPlane(const geometry::Patch& patch, const CrossingLines& lines, const gp_Vec& normal,
                          const LineWindow& window) {
  bool below = false, above = false;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  const TColgp_Array2OfPnt& poles = patch.surface->Poles();
  for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i)
    for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j) {
      const double s = side(lines, normal, poles(i, j));
      below = below || s <= 0.0;
      above = above || s >= 0.0;
      const double t = lines.lineThrough(poles(i, j));
      low = std::min(low, t), high = std::max(high, t);
    }
  const double slack = 1e-9 * (high - low);
  return below && above && high >= window.low - slack && low <= window.high + slack;
}

/// The root of f between a and b, where f changes sign (f(a) = fa, f(b) = fb): regula falsi
/// with the Illinois correction, which keeps the bracket and converges superlinearly.
template <typename Function>
double bracketedRoot(const Function& f, double a, double b, double fa, double fb) {
  int side = 0;
  for (int step = 0; step < 100 && b - a > 1e-15 * (std::abs(a) + std::abs(b) + 1.0); ++step) {
    const double c = (a * fb - b * fa) / (fb - fa);
    const double fc = f(c);
    if (fc == 0.0) return c;
    if ((fc < 0.0) == (fb < 0.0)) {
      b = c;
      fb = fc;
      if (side == -1) fa /= 2.0;
      side = -1;
    } else {
      a = c;
      fa = fc;
      if (side == 1) fb /= 2.0;
      side = 1;
    }
  }
  return std::abs(fa) < std::abs(fb) ? a : b;
}

/// The parameters where the plane crosses a boundary curve of the patch, given as a B-spline
/// over [a, b]: only spans whose poles lie on both sides can hold a crossing (a B-spline
/// changes sign no more often than its poles do); those are sampled and bisected.
std::vector<double> planeCrossings(const Handle(Geom_BSplineCurve) & curve, const CrossingLines& lines,
                                   const gp_Vec& normal) {
  const int degree = curve->Degree(), poles = curve->NbPoles();
  TColStd_Array1OfReal flat(1, poles + degree + 1);
  curve->KnotSequence(flat);
  const auto valueAt = [&](double parameter) { return side(lines, normal, curve->Value(parameter)); };
  std::vector<double> roots;
  for (int i = degree + 1; i <= poles; ++i) {
    const double a = flat(i), b = flat(i + 1);
    if (b <= a) continue;
    bool below = false, above = false;
    for (int k = i - degree; k <= i; ++k) {
      const double s = side(lines, normal, curve->Pole(k));
      below = below || s <= 0.0;
      above = above || s >= 0.0;
    }
    if (!below || !above) continue;
    constexpr int kStepsPerSpan = 4;
    double previousParameter = a, previousValue = valueAt(a);
    for (int k = 1; k <= kStepsPerSpan; ++k) {
      const double parameter = a + (b - a) * k / kStepsPerSpan;
      const double value = valueAt(parameter);
      if (previousValue == 0.0)
        roots.push_back(previousParameter);
      else if (previousValue * value < 0.0)
        roots.push_back(bracketedRoot(valueAt, previousParameter, parameter, previousValue, value));
      previousParameter = parameter;
      previousValue = value;
    }
    if (i == poles && previousValue == 0.0) roots.push_back(b);
  }
  return roots;
}

/// Where the plane crosses the patch's boundary, sorted by t, corners found twice kept once.
std::vector<geometry::PatchPoint> boundaryCrossings(const geometry::Patch& patch, const CrossingLines& lines,
                                                    const gp_Vec& normal) {
  std::vector<geometry::PatchPoint> crossings;
  const auto add = [&](double u, double v) {
    const gp_Pnt point = patch.surface->Value(u, v);
    for (const geometry::PatchPoint& known : crossings)
      if (known.point.Distance(point) < 1e-12 * (1.0 + gp_Vec(point.XYZ()).Magnitude())) return;
    crossings.push_back({lines.lineThrough(point), u, v, point});
  };
  for (double u : {patch.u0, patch.u1}) {
    const auto iso = Handle(Geom_BSplineCurve)::DownCast(patch.surface->UIso(u));
    for (double v : planeCrossings(iso, lines, normal)) add(u, v);
  }
  for (double v : {patch.v0, patch.v1}) {
    const auto iso = Handle(Geom_BSplineCurve)::DownCast(patch.surface->VIso(v));
    for (double u : planeCrossings(iso, lines, normal)) add(u, v);
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const geometry::PatchPoint& a, const geometry::PatchPoint& b) { return a.t < b.t; });
  return crossings;
}

/// The point where the line at t meets the patch (from the guess in `point`), and in
/// `tangent` the crossing's derivative along t there: from S(u, v) = base(t) + s * across,
/// Su u' + Sv v' - across s' = along.
bool meetLineAt(const geometry::Patch& patch, const CrossingLines& lines, double t, geometry::PatchPoint& point,
                gp_Vec& tangent) {
  if (!geometry::meetLine(patch, lines.base(t), lines.across, point)) return false;
  point.t = t;
  gp_Pnt surfacePoint;
  gp_Vec du, dv;
  patch.surface->D1(point.u, point.v, surfacePoint, du, dv);
  gp_XYZ rates = lines.along.XYZ();
  rates.Multiply(gp_Mat(du.XYZ(), dv.XYZ(), lines.across.Reversed().XYZ()).Inverted());
  tangent = rates.X() * du + rates.Y() * dv;
  return true;
}

/// The piece of the crossing on one patch from `first` to `last` (already on the patch),
/// sampled where the lines meet the patch, each from the patch parameters of its neighbours.
Handle(Geom_BSplineCurve)
    tracePiece(const geometry::Patch& patch, const CrossingLines& lines, const geometry::PatchPoint& first,
               const geometry::PatchPoint& last, double tolerance) {
  const CurveSampler sample = [&](double t, const CurveSample& before, const CurveSample& after) {
    const double share = after.t == before.t ? 0.0 : (t - before.t) / (after.t - before.t);
    const gp_XY guess = before.where.XY() + share * (after.where.XY() - before.where.XY());
    geometry::PatchPoint point{t, guess.X(), guess.Y(), {}};
    gp_Vec tangent;
    if (!meetLineAt(patch, lines, t, point, tangent)) return std::optional<CurveSample>();
    return std::optional<CurveSample>(CurveSample{t, point.point, tangent, gp_Pnt2d(point.u, point.v)});
  };
  const auto sampleOf = [](const geometry::PatchPoint& point) {
    return CurveSample{point.t, point.point, gp_Vec(), gp_Pnt2d(point.u, point.v)};
  };
  return fittedCurve(sample, sampleOf(first), sampleOf(last), tolerance);
}

/// The crossing's curve in a patch's parameters: where f(u, v) = n · (S(u, v) - origin) is 0.
class LevelCurve {
 public:
  LevelCurve(const geometry::Patch& patch, const CrossingLines& lines) : patch_(patch), lines_(lines) {
    normal_ = lines.planeNormal();
  }

  /// Moves (u, v) onto the curve along the gradient of f (Newton's method); false where f has
  /// no gradient (the plane touches the patch) or the point leaves the patch.
  bool settle(double& u, double& v) const {
    for (int iteration = 0; iteration < 30; ++iteration) {
      gp_Pnt point;
      gp_Vec du, dv;
      patch_.surface->D1(u, v, point, du, dv);
      const double f = gp_Vec(lines_.origin, point).Dot(normal_), fu = du.Dot(normal_), fv = dv.Dot(normal_);
      const double slope = fu * fu + fv * fv;
      if (slope <= 1e-30) return false;
      const double nextU = u - f * fu / slope, nextV = v - f * fv / slope;
      if (nextU < patch_.u0 - kOutside * (patch_.u1 - patch_.u0) ||
          nextU > patch_.u1 + kOutside * (patch_.u1 - patch_.u0) ||
          nextV < patch_.v0 - kOutside * (patch_.v1 - patch_.v0) ||
          nextV > patch_.v1 + kOutside * (patch_.v1 - patch_.v0))
        return false;
      const bool settled = std::abs(nextU - u) <= 1e-14 * (patch_.u1 - patch_.u0) &&
                           std::abs(nextV - v) <= 1e-14 * (patch_.v1 - patch_.v0);
      u = std::clamp(nextU, patch_.u0, patch_.u1);
      v = std::clamp(nextV, patch_.v0, patch_.v1);
      if (settled) return true;
    }
    return false;
  }

  /// The curve's unit direction in space at (u, v) and the step in (u, v) per unit of length
  /// along it, both turned by `sense` (+1 or -1).
  bool direction(double u, double v, double sense, gp_Vec& tangent, gp_Vec2d& rate) const {
    gp_Pnt point;
    gp_Vec du, dv;
    patch_.surface->D1(u, v, point, du, dv);
    const gp_Vec2d across(-dv.Dot(normal_), du.Dot(normal_));
    const gp_Vec along = across.X() * du + across.Y() * dv;
    if (along.Magnitude() <= 1e-300) return false;
    tangent = sense * along / along.Magnitude();
    rate = sense * across / along.Magnitude();
    return true;
  }

  gp_Pnt point(double u, double v) const { return patch_.surface->Value(u, v); }
  bool inside(double u, double v) const { return u >= patch_.u0 && u <= patch_.u1 && v >= patch_.v0 && v <= patch_.v1; }

 private:
  static constexpr double kOutside = 1e-9;
  const geometry::Patch& patch_;
  const CrossingLines& lines_;
  gp_Vec normal_;
};

/// The sense in which the curve runs from `first` towards `last`: into the patch where
/// `first` lies on its boundary and only one sense enters it, else towards `last`.
std::optional<double> senseFrom(const LevelCurve& curve, const geometry::PatchPoint& first,
                                const geometry::PatchPoint& last) {
  const double length = first.point.Distance(last.point);
  std::optional<double> entering;
  int entered = 0;
  for (double sense : {1.0, -1.0}) {
    gp_Vec tangent;
    gp_Vec2d rate;
    if (!curve.direction(first.u, first.v, sense, tangent, rate)) return std::nullopt;
    const double step = 1e-4 * length;
    if (curve.inside(first.u + step * rate.X(), first.v + step * rate.Y())) {
      ++entered;
      entering = sense;
    }
  }
  if (entered == 1) return entering;
  gp_Vec tangent;
  gp_Vec2d rate;
  curve.direction(first.u, first.v, 1.0, tangent, rate);
  return tangent.Dot(gp_Vec(first.point, last.point)) >= 0.0 ? 1.0 : -1.0;
}

/// The cubic through points of the crossing and their directions, parametrised by the length
/// between them, with points added until the crossing halfway between any two is within the
/// tolerance: through their directions at every point (a Hermite cubic) or only at the ends
/// (a C2 cubic); null when twelve rounds of added points do not make it follow the crossing.
Handle(Geom_BSplineCurve) fitAlongCurve(const LevelCurve& curve, double sense, std::vector<geometry::PatchPoint> points,
                                        std::vector<gp_Vec> tangents, double tolerance, bool everyDerivative) {
  for (int round = 0; round < 12; ++round) {
    std::vector<CurveSample> nodes;
    double parameter = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i > 0) parameter += points[i].point.Distance(points[i - 1].point);
      nodes.push_back({parameter, points[i].point, tangents[i], gp_Pnt2d(points[i].u, points[i].v)});
    }
    Handle(Geom_BSplineCurve) fitted = cubicThrough(nodes, everyDerivative);
    if (fitted.IsNull()) return nullptr;
    std::vector<geometry::PatchPoint> refinedPoints{points.front()};
    std::vector<gp_Vec> refinedTangents{tangents.front()};
    bool strayed = false;
    for (std::size_t i = 1; i < points.size(); ++i) {
      double u = 0.5 * (points[i - 1].u + points[i].u), v = 0.5 * (points[i - 1].v + points[i].v);
      gp_Vec tangent;
      gp_Vec2d rate;
      if (!curve.settle(u, v) || !curve.direction(u, v, sense, tangent, rate)) return nullptr;
      const gp_Pnt middle = curve.point(u, v);
      const double at = 0.5 * (nodes[i - 1].t + nodes[i].t);
      gp_Pnt onFit;
      gp_Vec fitTangent;
      fitted->D1(at, onFit, fitTangent);
      gp_Vec off(onFit, middle);
      if (fitTangent.Magnitude() > 0.0) off -= off.Dot(fitTangent.Normalized()) * fitTangent.Normalized();
      if (off.Magnitude() > tolerance) {
        strayed = true;
        refinedPoints.push_back({0.0, u, v, middle});
        refinedTangents.push_back(tangent);
      }
      refinedPoints.push_back(points[i]);
      refinedTangents.push_back(tangents[i]);
    }
    if (!strayed) return fitted;
    points = refinedPoints;
    tangents = refinedTangents;
  }
  return nullptr;
}

/// The piece of the crossing from `first` to `last` traced along the curve itself, for a
/// piece no line of the family meets once (a plate round a leading edge, where the lines along
/// up touch the skin): steps along the curve's direction, each settled onto it, shortened
/// where the direction turns fast; the points then joined by a cubic (fitAlongCurve): the C2
/// cubic where it follows the crossing, else the Hermite cubic. The C2 cubic is preferred for
/// the reason fittedCurve gives: OCCT's intersections treat each C2 piece of an edge on its own.
Handle(Geom_BSplineCurve)
    traceAlongCurve(const geometry::Patch& patch, const CrossingLines& lines, const geometry::PatchPoint& first,
                    const geometry::PatchPoint& last, double tolerance) {
  const LevelCurve curve(patch, lines);
  const std::optional<double> sense = senseFrom(curve, first, last);
  if (!sense) return nullptr;
  const double length = first.point.Distance(last.point);
  std::vector<geometry::PatchPoint> points{first};
  std::vector<gp_Vec> tangents(1);
  gp_Vec2d rate;
  if (!curve.direction(first.u, first.v, *sense, tangents[0], rate)) return nullptr;
  double step = length / 16.0;
  for (int steps = 0; steps < 4000; ++steps) {
    const geometry::PatchPoint& here = points.back();
    if (here.point.Distance(last.point) <= 1.5 * step && gp_Vec(here.point, last.point).Dot(tangents.back()) > 0.0) {
      gp_Vec tangent;
      if (!curve.direction(last.u, last.v, *sense, tangent, rate)) return nullptr;
      points.push_back(last);
      tangents.push_back(tangent);
      break;
    }
    gp_Vec tangent;
    curve.direction(here.u, here.v, *sense, tangent, rate);
    double u = here.u + step * rate.X(), v = here.v + step * rate.Y();
    gp_Vec nextTangent;
    if (!curve.settle(u, v) || !curve.direction(u, v, *sense, nextTangent, rate) || nextTangent.Angle(tangent) > 0.15) {
      step /= 2.0;
      if (step < 1e-9 * length) return nullptr;
      continue;
    }
    const gp_Pnt point = curve.point(u, v);
    if (point.Distance(here.point) < 1e-3 * step) return nullptr;  // held at the patch's boundary
    points.push_back({0.0, u, v, point});
    tangents.push_back(nextTangent);
    step = std::min(step * 1.5, length / 4.0);
  }
  if (points.back().point.Distance(last.point) > 0.0) return nullptr;
  Handle(Geom_BSplineCurve) smooth = fitAlongCurve(curve, *sense, points, tangents, tolerance, false);
  return !smooth.IsNull() ? smooth : fitAlongCurve(curve, *sense, points, tangents, tolerance, true);
}

/// The point of the patch on the line at t, starting from the patch parameters that the line
/// has between two known crossings.
std::optional<geometry::PatchPoint> pointBetween(const geometry::Patch& patch, const CrossingLines& lines,
                                                 const geometry::PatchPoint& a, const geometry::PatchPoint& b,
                                                 double t) {
  const double share = (t - a.t) / (b.t - a.t);
  geometry::PatchPoint point{t, a.u + share * (b.u - a.u), a.v + share * (b.v - a.v), {}};
  gp_Vec tangent;
  if (!meetLineAt(patch, lines, t, point, tangent)) return std::nullopt;
  return point;
}

/// The boundary of the patch a point on it lies on, when that boundary is a straight line
/// (within the tolerance at three points between its corners): its corners.
std::optional<SkinCrossing::StraightEdge> straightBoundaryAt(const geometry::Patch& patch,
                                                             const geometry::PatchPoint& point, double tolerance) {
  const double uSlack = 1e-9 * (patch.u1 - patch.u0), vSlack = 1e-9 * (patch.v1 - patch.v0);
  std::function<gp_Pnt(double)> along;
  if (std::abs(point.u - patch.u0) <= uSlack || std::abs(point.u - patch.u1) <= uSlack) {
    const double u = std::abs(point.u - patch.u0) <= uSlack ? patch.u0 : patch.u1;
    along = [&patch, u](double share) { return patch.surface->Value(u, patch.v0 + share * (patch.v1 - patch.v0)); };
  } else if (std::abs(point.v - patch.v0) <= vSlack || std::abs(point.v - patch.v1) <= vSlack) {
    const double v = std::abs(point.v - patch.v0) <= vSlack ? patch.v0 : patch.v1;
    along = [&patch, v](double share) { return patch.surface->Value(patch.u0 + share * (patch.u1 - patch.u0), v); };
  } else {
    return std::nullopt;
  }
  const gp_Pnt first = along(0.0), last = along(1.0);
  const gp_Vec chord(first, last);
  if (chord.Magnitude() <= tolerance) return std::nullopt;
  for (double share : {0.25, 0.5, 0.75}) {
    const gp_Vec off(first, along(share));
    if (off.Crossed(chord.Normalized()).Magnitude() > tolerance) return std::nullopt;
  }
  return SkinCrossing::StraightEdge{first, last};
}

/// A patch the plane crosses, from one boundary crossing to the other.
struct CrossedPatch {
  geometry::Patch patch;
  geometry::PatchPoint entry, exit;
};

/// The t at which a trace ends on the crossed patches (sorted, meeting end to end): its
/// line's, where its border meets the skin, or the skin's first (last) crossing when open.
std::optional<double> endOn(const std::vector<CrossedPatch>& crossed, const CrossingLines& lines,
                            const CrossingEnd& end, bool isStart) {
  switch (end.kind) {
    case CrossingEnd::Kind::Open:
      return isStart ? crossed.front().entry.t : crossed.back().exit.t;
    case CrossingEnd::Kind::AtLine:
      return end.t;
    case CrossingEnd::Kind::AtBorder:
      break;
  }
  // The border runs close to the family's line through its point: start from the skin there.
  const double near = lines.lineThrough(end.through);
  for (const CrossedPatch& patch : crossed) {
    if (near < patch.entry.t || near > patch.exit.t) continue;
    std::optional<geometry::PatchPoint> point = pointBetween(patch.patch, lines, patch.entry, patch.exit, near);
    if (!point || !geometry::meetLine(patch.patch, end.through, end.direction, *point)) return std::nullopt;
    return lines.lineThrough(point->point);
  }
  return std::nullopt;
}

/// The crossed patches in runs along the lines, each patch entered where the one before it in
/// its run is left (within the tolerance).
std::vector<std::vector<CrossedPatch>> runsOf(std::vector<CrossedPatch> crossed, double tolerance) {
  std::sort(crossed.begin(), crossed.end(),
            [](const CrossedPatch& a, const CrossedPatch& b) { return a.entry.t < b.entry.t; });
  std::vector<std::vector<CrossedPatch>> runs;
  for (const CrossedPatch& patch : crossed) {
    const auto run = std::find_if(runs.begin(), runs.end(), [&](const std::vector<CrossedPatch>& candidate) {
      return candidate.back().exit.point.Distance(patch.entry.point) <= tolerance;
    });
    if (run == runs.end())
      runs.push_back({patch});
    else
      run->push_back(patch);
  }
  return runs;
}

/// Whether a range of t meets the lines between t = 0 and t = 1.
bool meetsUnitRange(double low, double high) { return high >= 0.0 && low <= 1.0; }

/// The patches the plane crosses, each once, sorted along the lines, each entered where the one
/// before is left. Where the plane crosses the skin in separate runs (the far side of a closed box surface,
/// further along the plane), the run that meets
/// the lines between t = 0 and 1, where the family is set up (a web's piece between its
/// positions, a plate between its ends). Nothing when a face is no untrimmed patch, no run or
/// more than one meets those lines, or a face the plane crosses other than once lies along
/// the run. Faces whose poles' lines miss `window` are not looked at.
std::optional<std::vector<CrossedPatch>> crossedPatches(const TopoDS_Shape& skin, const CrossingLines& lines,
                                                        double tolerance, const LineWindow& window = {}) {
  const gp_Vec normal = lines.planeNormal();
  std::vector<CrossedPatch> crossed;
  std::vector<std::pair<double, double>> unclear;  // the t ranges of faces crossed other than once
  for (TopExp_Explorer explorer(skin, TopAbs_FACE); explorer.More(); explorer.Next()) {
    const std::optional<geometry::Patch> patch = geometry::patchOf(TopoDS::Face(explorer.Current()));
    if (!patch) return std::nullopt;
    if (!poleHullCrossesPlane(*patch, lines, normal, window)) continue;
    const std::vector<geometry::PatchPoint> crossings = boundaryCrossings(*patch, lines, normal);
    if (crossings.empty()) continue;
    if (crossings.size() != 2 || crossings[1].t - crossings[0].t <= 0.0)
      unclear.emplace_back(crossings.front().t, crossings.back().t);
    else
      crossed.push_back({*patch, crossings[0], crossings[1]});
  }
  std::vector<std::vector<CrossedPatch>> runs = runsOf(crossed, tolerance);
  if (runs.size() > 1)
    runs.erase(std::remove_if(runs.begin(), runs.end(),
                              [](const std::vector<CrossedPatch>& run) {
                                return !meetsUnitRange(run.front().entry.t, run.back().exit.t);
                              }),
               runs.end());
  if (runs.size() != 1) return std::nullopt;
  const double low = runs.front().front().entry.t, high = runs.front().back().exit.t;
  for (const auto& [first, last] : unclear)
    if (last >= low && first <= high) return std::nullopt;
  return runs.front();
}

}  // namespace

std::optional<std::pair<double, double>> crossingSpan(const TopoDS_Shape& skin, const CrossingLines& lines,
                                                      double tolerance) {
  const auto crossed = crossedPatches(skin, lines, tolerance);
  if (!crossed) return std::nullopt;
  return std::make_pair(crossed->front().entry.t, crossed->back().exit.t);
}

std::optional<SkinCrossing> traceSkinCrossing(const TopoDS_Shape& skin, const CrossingLines& lines,
                                              const CrossingEnd& fromEnd, const CrossingEnd& toEnd, double tolerance) {
  // Only faces that can reach between the ends are looked at (a web's piece along a lifting surface
  // of fifty segments meets two or three).
  LineWindow window;
  if (fromEnd.kind == CrossingEnd::Kind::AtLine) window.low = fromEnd.t;
  if (toEnd.kind == CrossingEnd::Kind::AtLine) window.high = toEnd.t;
  auto found = crossedPatches(skin, lines, tolerance, window);
  if (!found) return std::nullopt;
  std::vector<CrossedPatch>& crossed = *found;
  for (std::size_t i = 1; i < crossed.size(); ++i)
    crossed[i].entry.point = crossed[i - 1].exit.point;  // one point where two patches meet
  const double first = crossed.front().entry.t, last = crossed.back().exit.t;
  const double slack = 1e-12 * (last - first);
  const std::optional<double> from = endOn(crossed, lines, fromEnd, true), to = endOn(crossed, lines, toEnd, false);
  if (!from || !to || *from < first - slack || *to > last + slack) return std::nullopt;  // the skin ends short
  if (*to - *from <= slack) return std::nullopt;
  SkinCrossing crossing;
  for (const CrossedPatch& patch : crossed) {
    const double a = std::max(patch.entry.t, *from), b = std::min(patch.exit.t, *to);
    if (b - a <= slack) continue;
    const auto start =
        a - patch.entry.t <= slack ? patch.entry : pointBetween(patch.patch, lines, patch.entry, patch.exit, a);
    const auto end =
        patch.exit.t - b <= slack ? patch.exit : pointBetween(patch.patch, lines, patch.entry, patch.exit, b);
    if (!start || !end) return std::nullopt;
    geometry::PatchPoint startPoint = *start;
    if (!crossing.pieces.empty()) startPoint.point = crossing.pieces.back()->EndPoint();
    Handle(Geom_BSplineCurve) piece = tracePiece(patch.patch, lines, startPoint, *end, tolerance);
    if (piece.IsNull()) piece = traceAlongCurve(patch.patch, lines, startPoint, *end, tolerance);
    if (piece.IsNull()) return std::nullopt;
    crossing.pieces.push_back(piece);
  }
  if (crossing.pieces.empty()) return std::nullopt;
  if (fromEnd.kind == CrossingEnd::Kind::Open)
    crossing.startEdge = straightBoundaryAt(crossed.front().patch, crossed.front().entry, tolerance);
  if (toEnd.kind == CrossingEnd::Kind::Open)
    crossing.endEdge = straightBoundaryAt(crossed.back().patch, crossed.back().exit, tolerance);
  return crossing;
}

}  // namespace airshape::geometry
