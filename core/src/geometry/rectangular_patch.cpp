#include "rectangular_patch.h"

#include <cmath>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

namespace airshape::geometry {

namespace {

/// The degree a trigonometric polynomial of low order is integrated as on an eighth of a turn.
constexpr int kTurnDegree = 6;

/// Whether a parameter-space curve runs along u or along v: a line parallel to an axis, or
/// (as sewing leaves them) a B-spline whose poles all share one coordinate.
bool isIsoLine(Handle(Geom2d_Curve) pcurve) {
  while (const auto trimmed = Handle(Geom2d_TrimmedCurve)::DownCast(pcurve)) pcurve = trimmed->BasisCurve();
  if (const auto line = Handle(Geom2d_Line)::DownCast(pcurve)) {
    const gp_Dir2d direction = line->Direction();
    return std::abs(direction.X()) <= 1e-12 || std::abs(direction.Y()) <= 1e-12;
  }
  const auto spline = Handle(Geom2d_BSplineCurve)::DownCast(pcurve);
  if (spline.IsNull()) return false;
  bool sameU = true, sameV = true;
  const gp_Pnt2d start = spline->Pole(1);
  for (int i = 2; i <= spline->NbPoles(); ++i) {
    sameU = sameU && std::abs(spline->Pole(i).X() - start.X()) <= 1e-12;
    sameV = sameV && std::abs(spline->Pole(i).Y() - start.Y()) <= 1e-12;
  }
  return sameU || sameV;
}

/// Whether the face fills the rectangle of its parameter bounds. Iso-lines are straight in the
/// parameter plane, so the area they enclose there is the polygon of their ends; only when it
/// fills the bounding rectangle is the face that rectangle (a notched face, as a cut leaves it,
/// is bounded by iso-lines too).
bool fillsItsRectangle(const TopoDS_Face& face, double u0, double u1, double v0, double v1) {
  double enclosed = 0.0;
  for (TopExp_Explorer edges(face, TopAbs_EDGE); edges.More(); edges.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges.Current());
    double first, last;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (pcurve.IsNull() || !isIsoLine(pcurve)) return false;
    gp_Pnt2d from = pcurve->Value(first), to = pcurve->Value(last);
    if (edge.Orientation() == TopAbs_REVERSED) std::swap(from, to);
    enclosed += 0.5 * (from.X() * to.Y() - to.X() * from.Y());
  }
  const double rectangle = (u1 - u0) * (v1 - v0);
  return std::abs(std::abs(enclosed) - rectangle) <= 1e-9 * rectangle;
}

/// [from, to] (an angle) in eighths of a turn or less.
std::vector<double> turnBreaks(double from, double to) {
  const int count = std::max(1, static_cast<int>(std::ceil((to - from) / (M_PI / 4.0) - 1e-9)));
  std::vector<double> result;
  for (int i = 0; i <= count; ++i) result.push_back(from + (to - from) * i / count);
  return result;
}

/// The spans and degree along a profile curve: its knots where it is a polynomial B-spline, one
/// span of degree 1 where it is a line; false for any other curve.
bool curveSpans(Handle(Geom_Curve) curve, double from, double to, std::vector<double>& spans, int& degree) {
  while (const auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(curve)) curve = trimmed->BasisCurve();
  if (const auto spline = Handle(Geom_BSplineCurve)::DownCast(curve); !spline.IsNull() && !spline->IsRational()) {
    spans = knotBreaks(spline->Knots(), from, to);
    degree = spline->Degree();
    return true;
  }
  if (!Handle(Geom_Line)::DownCast(curve).IsNull()) {
    spans = {from, to};
    degree = 1;
    return true;
  }
  return false;
}

/// The spans and degrees of the patch's surface, once its bounds are set; false where its
/// integrands are not taken span by span.
bool setSpans(RectangularPatch& patch) {
  Handle(Geom_Surface) surface = patch.surface;
  while (const auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface))
    surface = trimmed->BasisSurface();
  if (const auto spline = Handle(Geom_BSplineSurface)::DownCast(surface); !spline.IsNull()) {
    if (spline->IsURational() || spline->IsVRational()) return false;
    patch.uBreaks = knotBreaks(spline->UKnots(), patch.u0, patch.u1);
    patch.vBreaks = knotBreaks(spline->VKnots(), patch.v0, patch.v1);
    patch.uDegree = spline->UDegree();
    patch.vDegree = spline->VDegree();
    return true;
  }
  const bool turned = !Handle(Geom_SurfaceOfRevolution)::DownCast(surface).IsNull() ||
                      !Handle(Geom_CylindricalSurface)::DownCast(surface).IsNull() ||
                      !Handle(Geom_ConicalSurface)::DownCast(surface).IsNull() ||
                      !Handle(Geom_SphericalSurface)::DownCast(surface).IsNull() ||
                      !Handle(Geom_ToroidalSurface)::DownCast(surface).IsNull();
  if (!turned) return false;
  patch.uBreaks = turnBreaks(patch.u0, patch.u1);
  patch.uDegree = kTurnDegree;
  if (const auto revolution = Handle(Geom_SurfaceOfRevolution)::DownCast(surface))
    return curveSpans(revolution->BasisCurve(), patch.v0, patch.v1, patch.vBreaks, patch.vDegree);
  if (!Handle(Geom_SphericalSurface)::DownCast(surface).IsNull() ||
      !Handle(Geom_ToroidalSurface)::DownCast(surface).IsNull()) {
    // Turned about a second axis too: v is an angle as well.
    patch.vBreaks = turnBreaks(patch.v0, patch.v1);
    patch.vDegree = kTurnDegree;
    return true;
  }
  // A cylinder's or a cone's lines: the integrands are polynomials of degree 2 along them.
  patch.vBreaks = {patch.v0, patch.v1};
  patch.vDegree = 2;
  return true;
}

}  // namespace

std::vector<double> knotBreaks(const TColStd_Array1OfReal& knots, double from, double to) {
  std::vector<double> result = {from};
  for (int i = knots.Lower(); i <= knots.Upper(); ++i)
    if (knots(i) > from + 1e-12 && knots(i) < to - 1e-12) result.push_back(knots(i));
  result.push_back(to);
  return result;
}

std::optional<RectangularPatch> rectangularPatch(const TopoDS_Face& face) {
  RectangularPatch patch;
  patch.surface = BRep_Tool::Surface(face);
  if (patch.surface.IsNull()) return std::nullopt;
  BRepTools::UVBounds(face, patch.u0, patch.u1, patch.v0, patch.v1);
  if (!setSpans(patch) || !fillsItsRectangle(face, patch.u0, patch.u1, patch.v0, patch.v1)) return std::nullopt;
  return patch;
}

}  // namespace airshape::geometry
