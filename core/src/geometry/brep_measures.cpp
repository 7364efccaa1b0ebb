#include "airshape/geometry/brep_measures.h"

#include <cmath>
#include <optional>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Plane.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>

#include "airshape/geometry/gauss_rule.h"
#include "airshape/parallel_for.h"
#include "rectangular_patch.h"

namespace airshape::geometry {

namespace {

constexpr double kIntegrationAccuracy = 1e-9;
/// Intervals per direction of a coarse integration (a sign, a scale): a few dozen points per
/// face where a lofted body's skin has hundreds of spans.
constexpr int kCoarseIntervals = 8;

/// The faces of a shape, each as often and with the orientation the shape uses it.
std::vector<TopoDS_Face> facesOf(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer explorer(shape, TopAbs_FACE); explorer.More(); explorer.Next())
    faces.push_back(TopoDS::Face(explorer.Current()));
  return faces;
}

/// Each face's measure, the faces on every core where there are many knot spans to integrate
/// (a guided body's skin: 800,000, seconds on one core), else one after the other
/// (starting threads costs more than the few spans of a ruled surface's faces).
template <typename Measure>
std::vector<double> measuredFaces(const std::vector<TopoDS_Face>& faces,
                                  const std::vector<std::optional<RectangularPatch>>& patches, Measure measure) {
  constexpr std::size_t kSpansWorthEveryCore = 20000;
  std::size_t spans = 0;
  for (const auto& patch : patches)
    if (patch) spans += (patch->uBreaks.size() - 1) * (patch->vBreaks.size() - 1);
  std::vector<double> measures(faces.size(), 0.0);
  const auto one = [&](std::size_t index) { measures[index] = measure(faces[index], patches[index]); };
  if (spans >= kSpansWorthEveryCore)
    parallelFor(faces.size(), one);
  else
    for (std::size_t index = 0; index < faces.size(); ++index) one(index);
  return measures;
}

/// Each face as a rectangular patch, where it is one.
std::vector<std::optional<RectangularPatch>> patchesOf(const std::vector<TopoDS_Face>& faces) {
  std::vector<std::optional<RectangularPatch>> patches;
  for (const TopoDS_Face& face : faces) patches.push_back(rectangularPatch(face));
  return patches;
}

/// At most `count` equal intervals of [from, to], fewer where the patch has fewer spans there
/// (then its spans).
std::vector<double> coarseBreaks(const std::vector<double>& spans, int count) {
  if (static_cast<int>(spans.size()) - 1 <= count) return spans;
  std::vector<double> result;
  const double from = spans.front(), to = spans.back();
  for (int i = 0; i <= count; ++i) result.push_back(from + (to - from) * i / count);
  return result;
}

/// ∫∫ f(P, S_u, S_v) du dv over one cell [u0, u1] × [v0, v1] by the product rule of `uRule`
/// and `vRule`.
template <typename Integrand>
double cellIntegral(const GeomAdaptor_Surface& evaluator, const GaussRule& uRule, const GaussRule& vRule, double u0,
                    double u1, double v0, double v1, const Integrand& integrand) {
  const double uMid = 0.5 * (u0 + u1), uHalf = 0.5 * (u1 - u0), vMid = 0.5 * (v0 + v1), vHalf = 0.5 * (v1 - v0);
  double sum = 0.0;
  for (int a = 1; a <= uRule.points.Length(); ++a)
    for (int b = 1; b <= vRule.points.Length(); ++b) {
      gp_Pnt p;
      gp_Vec du, dv;
      evaluator.D1(uMid + uHalf * uRule.points(a), vMid + vHalf * vRule.points(b), p, du, dv);
      sum += uRule.weights(a) * vRule.weights(b) * integrand(p, du, dv);
    }
  return sum * uHalf * vHalf;
}

/// The same over the patch, cell by cell between the given breaks, with the given numbers of
/// Gauss points per direction.
template <typename Integrand>
double integrateBetweenBreaks(const RectangularPatch& patch, const std::vector<double>& uBreaks,
                              const std::vector<double>& vBreaks, int uPoints, int vPoints, Integrand integrand) {
  const GeomAdaptor_Surface evaluator(patch.surface);  // caches a B-spline's span polynomials
  const GaussRule uRule(uPoints), vRule(vPoints);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < uBreaks.size(); ++i)
    for (std::size_t j = 0; j + 1 < vBreaks.size(); ++j)
      sum += cellIntegral(evaluator, uRule, vRule, uBreaks[i], uBreaks[i + 1], vBreaks[j], vBreaks[j + 1], integrand);
  return sum;
}

/// The same span by span: a polynomial on each span is integrated exactly by enough points.
template <typename Integrand>
double integrateOverSpans(const RectangularPatch& patch, int uPoints, int vPoints, Integrand integrand) {
  return integrateBetweenBreaks(patch, patch.uBreaks, patch.vBreaks, uPoints, vPoints, integrand);
}

/// How a volume is integrated: exactly, or roughly (enough to tell its sign).
enum class Accuracy { Exact, Rough };

/// (P − O)·(S_u × S_v) about the point O: three times the volume integrand.
struct VolumeIntegrand {
  gp_XYZ origin;
  double operator()(const gp_Pnt& p, const gp_Vec& du, const gp_Vec& dv) const {
    return gp_Vec(p.XYZ() - origin).Dot(du.Crossed(dv));
  }
};

/// (1/3)∫∫ (P − O)·(S_u × S_v) du dv over the patch: on a B-spline a polynomial on every knot
/// span, so a Gauss rule with ceil(3p/2) points in a direction of degree p integrates it
/// exactly (on a turned surface, to rounding); two points per span and direction when rough.
double patchVolume(const RectangularPatch& patch, const gp_XYZ& origin, Accuracy accuracy) {
  const bool exact = accuracy == Accuracy::Exact;
  const int uPoints = exact ? (3 * patch.uDegree + 2) / 2 : 2;
  const int vPoints = exact ? (3 * patch.vDegree + 2) / 2 : 2;
  return integrateOverSpans(patch, uPoints, vPoints, VolumeIntegrand{origin}) / 3.0;
}

/// The same on a coarse grid (two Gauss points on each of at most kCoarseIntervals intervals
/// per direction, whatever the knots): a few dozen points per face where a lofted body's skin
/// has hundreds of spans.
double coarsePatchVolume(const RectangularPatch& patch, const gp_XYZ& origin) {
  return integrateBetweenBreaks(patch, coarseBreaks(patch.uBreaks, kCoarseIntervals),
                                coarseBreaks(patch.vBreaks, kCoarseIntervals), 2, 2, VolumeIntegrand{origin}) /
         3.0;
}

/// |S_u × S_v|: the area integrand.
struct AreaIntegrand {
  double operator()(const gp_Pnt&, const gp_Vec& du, const gp_Vec& dv) const { return du.Crossed(dv).Magnitude(); }
};

/// ∫∫ |S_u × S_v| over one cell by the product rule of `uRule` and `vRule`.
double cellArea(const GeomAdaptor_Surface& evaluator, const GaussRule& uRule, const GaussRule& vRule, double u0,
                double u1, double v0, double v1) {
  return cellIntegral(evaluator, uRule, vRule, u0, u1, v0, v1, AreaIntegrand{});
}

/// The Gauss rules an area is taken with, per direction of degree p: 2p + 4 points, and two
/// fewer to check it; where the direction has many knot spans (a guided body's skin has two
/// thousand round it), each span is so short that p + 1 points, checked by p, are as exact,
/// at a sixth of the evaluations.
struct AreaRules {
  static constexpr std::size_t kManySpans = 16;
  GaussRule u, v, uCheck, vCheck;
  explicit AreaRules(const RectangularPatch& patch)
      : u(points(patch.uDegree, patch.uBreaks)),
        v(points(patch.vDegree, patch.vBreaks)),
        uCheck(checkPoints(patch.uDegree, patch.uBreaks)),
        vCheck(checkPoints(patch.vDegree, patch.vBreaks)) {}
  static bool many(const std::vector<double>& breaks) { return breaks.size() > kManySpans; }
  static int points(int degree, const std::vector<double>& breaks) {
    return many(breaks) ? degree + 1 : 2 * degree + 4;
  }
  static int checkPoints(int degree, const std::vector<double>& breaks) {
    return many(breaks) ? degree : 2 * degree + 2;
  }
};

/// A cell's area, refined where the two rules disagree by more than `tolerance` (an absolute
/// area): |S_u × S_v| is smooth on a knot span unless S_u and S_v nearly line up somewhere in it
/// (a strongly cambered airfoil ruled over a long span), where the fixed rule is off by 6e-8 of
/// the area and OCCT's adaptive one too, or at a degenerate corner (a pointed tip). Such a cell is
/// halved both ways, at most kDeepest times (at six, D250's winglet segment was 2.4e-10 off
/// the limit; at eight it is there).
double refinedCellArea(const GeomAdaptor_Surface& evaluator, const AreaRules& rules, double u0, double u1, double v0,
                       double v1, double tolerance, int depth = 0) {
  constexpr int kDeepest = 8;
  const double area = cellArea(evaluator, rules.u, rules.v, u0, u1, v0, v1);
  if (depth == kDeepest) return area;
  const double check = cellArea(evaluator, rules.uCheck, rules.vCheck, u0, u1, v0, v1);
  if (std::abs(area - check) <= tolerance) return area;
  const double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1);
  return refinedCellArea(evaluator, rules, u0, u, v0, v, tolerance, depth + 1) +
         refinedCellArea(evaluator, rules, u, u1, v0, v, tolerance, depth + 1) +
         refinedCellArea(evaluator, rules, u0, u, v, v1, tolerance, depth + 1) +
         refinedCellArea(evaluator, rules, u, u1, v, v1, tolerance, depth + 1);
}

/// ∫∫ |S_u × S_v| du dv over the patch, span by span. Not a polynomial, but smooth on almost
/// every knot span: there the rules of AreaRules leave errors far below 1e-9, and the others
/// are refined until their two rules agree to 1e-13 of the whole patch's area (of a coarse
/// estimate of it): a tolerance of each span's own area would refine tiny spans at a
/// degenerate edge, where the integrand has a square root's kink, down to rounding.
double patchArea(const RectangularPatch& patch) {
  constexpr double kAgreement = 1e-13;
  const GeomAdaptor_Surface evaluator(patch.surface);
  const AreaRules rules(patch);
  const double estimate = integrateBetweenBreaks(patch, coarseBreaks(patch.uBreaks, kCoarseIntervals),
                                                 coarseBreaks(patch.vBreaks, kCoarseIntervals), 2, 2, AreaIntegrand{});
  const double tolerance = kAgreement * std::abs(estimate);
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < patch.uBreaks.size(); ++i)
    for (std::size_t j = 0; j + 1 < patch.vBreaks.size(); ++j)
      area += refinedCellArea(evaluator, rules, patch.uBreaks[i], patch.uBreaks[i + 1], patch.vBreaks[j],
                              patch.vBreaks[j + 1], tolerance);
  return area;
}

/// OCCT's volume of a solid: adaptive to 1e-9 when exact, its fixed Gauss rule when rough.
double occtVolume(const TopoDS_Shape& shape, Accuracy accuracy) {
  GProp_GProps properties;
  if (accuracy == Accuracy::Exact)
    BRepGProp::VolumeProperties(shape, properties, kIntegrationAccuracy);
  else
    BRepGProp::VolumeProperties(shape, properties);
  return properties.Mass();
}

/// ∮ n·((C - O) × C') dt / 2 along one edge's curve, in the direction the face runs it: the edge's
/// share of a plane face's area (Green's theorem). Polynomial on every knot span of a
/// non-rational B-spline (degree 2p − 1), so p + 1 Gauss points per span are exact there;
/// other curves are taken as B-splines (rational ones with more points, then only nearly
/// exact).
double edgeAreaShare(const TopoDS_Edge& edge, const gp_Dir& normal, const gp_Pnt& origin) {
  double first, last;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
  if (curve.IsNull()) return 0.0;  // a degenerate edge encloses nothing
  const Handle(Geom_BSplineCurve) spline = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, first, last));
  const GaussRule rule(spline->IsRational() ? 24 : spline->Degree() + 1);
  const GeomAdaptor_Curve evaluator(spline);
  const std::vector<double> spans = knotBreaks(spline->Knots(), spline->FirstParameter(), spline->LastParameter());
  const gp_Vec n(normal);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < spans.size(); ++i) {
    const double mid = 0.5 * (spans[i] + spans[i + 1]), half = 0.5 * (spans[i + 1] - spans[i]);
    for (int a = 1; a <= rule.points.Length(); ++a) {
      gp_Pnt p;
      gp_Vec d;
      evaluator.D1(mid + half * rule.points(a), p, d);
      sum += rule.weights(a) * half * n.Dot(gp_Vec(origin, p).Crossed(d));
    }
  }
  return (edge.Orientation() == TopAbs_REVERSED ? -0.5 : 0.5) * sum;
}

/// The signed area the edges of a face or wire enclose about `normal` (Green's theorem), taken
/// about a point of the boundary: where its edges meet only within their tolerance, the gaps
/// then add areas of the size of the boundary, not of its distance from the origin.
double areaAlong(const TopoDS_Shape& boundary, const gp_Dir& normal) {
  double area = 0.0;
  TopExp_Explorer vertex(boundary, TopAbs_VERTEX);
  const gp_Pnt origin = vertex.More() ? BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current())) : gp_Pnt();
  for (TopExp_Explorer edges(boundary, TopAbs_EDGE); edges.More(); edges.Next())
    area += edgeAreaShare(TopoDS::Edge(edges.Current()), normal, origin);
  return area;
}

/// The area of a plane face, exactly from its boundary (Green's theorem): robust where its
/// boundary curves have many knots, and cheaper than OCCT's integration over the face even
/// when only a rough value is needed (a fifth of its instructions on a lifting surface's caps).
double planeArea(const TopoDS_Face& face, const Geom_Plane& plane) {
  return std::abs(areaAlong(face, plane.Position().Direction()));
}

/// A plane face's share of the volume about O: (P − O)·n is constant on it.
double planeFaceVolume(const TopoDS_Face& face, const Geom_Plane& plane, const gp_XYZ& origin) {
  const gp_Ax3& axes = plane.Position();
  const double offset = gp_Vec(axes.Location().XYZ() - origin).Dot(gp_Vec(axes.Direction()));
  const double orientation = axes.Direct() ? 1.0 : -1.0;  // the plane's normal is X × Y
  return orientation * offset * planeArea(face, plane) / 3.0;
}

/// The point volumes are integrated about: the mean of the shape's vertices, each counted as
/// often as the shape's edges use it. Any point gives a closed shell's volume; one inside the
/// shape keeps the faces' shares small (no cancellation far from the origin), and it is
/// OCCT's choice, so that a solid whose shell is open (the reference's component segments)
/// measures what OCCT's integration of it gives.
gp_XYZ volumeOrigin(const TopoDS_Shape& solid) {
  gp_XYZ sum(0.0, 0.0, 0.0);
  int count = 0;
  for (TopExp_Explorer vertex(solid, TopAbs_VERTEX); vertex.More(); vertex.Next(), ++count)
    sum += BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current())).XYZ();
  return count > 0 ? sum / count : sum;
}

/// The faces' shares of a solid's volume about volumeOrigin, with their senses:
/// (1/3)∫ (P − O)·n dA, each by `patchShare` on a rectangular patch and exactly on a plane;
/// none when a face is neither (the terms of one formula only add up to the volume together,
/// so such a solid is integrated by OCCT as a whole).
template <typename PatchShare>
std::optional<std::vector<double>> volumeShares(const TopoDS_Shape& solid, PatchShare patchShare) {
  const gp_XYZ origin = volumeOrigin(solid);
  const std::vector<TopoDS_Face> faces = facesOf(solid);
  const std::vector<std::optional<RectangularPatch>> patches = patchesOf(faces);
  for (std::size_t index = 0; index < faces.size(); ++index)
    if (!patches[index] && Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(faces[index])).IsNull()) return std::nullopt;
  return measuredFaces(faces, patches, [&](const TopoDS_Face& face, const std::optional<RectangularPatch>& patch) {
    const double sense = face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
    if (patch) return sense * patchShare(*patch, origin);
    return sense * planeFaceVolume(face, *Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(face)), origin);
  });
}

double sum(const std::vector<double>& values) {
  double total = 0.0;
  for (double value : values) total += value;
  return total;
}

double signedVolume(const TopoDS_Shape& solid, Accuracy accuracy) {
  if (solid.IsNull()) return 0.0;
  const auto shares = volumeShares(solid, [accuracy](const RectangularPatch& patch, const gp_XYZ& origin) {
    return patchVolume(patch, origin, accuracy);
  });
  return shares ? sum(*shares) : occtVolume(solid, accuracy);
}

/// The volume from the coarse grid, where it can be trusted: where the faces' shares do not
/// nearly cancel (as they do on a solid of next to no volume), so
/// that the coarse rule's error, a small part of each share, cannot turn the sign.
std::optional<double> coarseSignedVolume(const TopoDS_Shape& solid) {
  constexpr double kTrustedShare = 0.05;
  const auto shares = volumeShares(solid, coarsePatchVolume);
  if (!shares) return std::nullopt;
  double magnitude = 0.0;
  for (double share : *shares) magnitude += std::abs(share);
  const double volume = sum(*shares);
  if (std::abs(volume) > kTrustedShare * magnitude) return volume;
  return std::nullopt;
}

}  // namespace

double volumeOf(const TopoDS_Shape& solid) { return std::abs(signedVolume(solid, Accuracy::Exact)); }

double roughSignedVolumeOf(const TopoDS_Shape& solid) {
  if (solid.IsNull()) return 0.0;
  if (const auto volume = coarseSignedVolume(solid)) return *volume;
  return signedVolume(solid, Accuracy::Rough);
}

double signedAreaEnclosed(const TopoDS_Wire& wire, const gp_Dir& normal) { return areaAlong(wire, normal); }

double areaOf(const TopoDS_Shape& faces) {
  if (faces.IsNull()) return 0.0;
  const std::vector<TopoDS_Face> all = facesOf(faces);
  const std::vector<double> areas =
      measuredFaces(all, patchesOf(all), [](const TopoDS_Face& face, const std::optional<RectangularPatch>& patch) {
        if (patch) return patchArea(*patch);
        if (const auto plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(face)); !plane.IsNull())
          return planeArea(face, *plane);
        GProp_GProps properties;
        BRepGProp::SurfaceProperties(face, properties, kIntegrationAccuracy);
        return properties.Mass();
      });
  return sum(areas);
}

double enclosedVolume(const TopoDS_Shape& shape) {
  double volume = 0.0;
  if (shape.IsNull()) return volume;
  for (TopExp_Explorer solids(shape, TopAbs_SOLID); solids.More(); solids.Next()) volume += volumeOf(solids.Current());
  for (TopExp_Explorer shells(shape, TopAbs_SHELL, TopAbs_SOLID); shells.More(); shells.Next())
    if (BRep_Tool::IsClosed(shells.Current())) volume += volumeOf(shells.Current());
  return volume;
}

double lengthOf(const TopoDS_Shape& edges) {
  double length = 0.0;
  if (edges.IsNull()) return length;
  for (TopExp_Explorer explorer(edges, TopAbs_EDGE); explorer.More(); explorer.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(explorer.Current());
    if (BRep_Tool::Degenerated(edge)) continue;
    length += GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge), kIntegrationAccuracy);
  }
  return length;
}

}  // namespace airshape::geometry
