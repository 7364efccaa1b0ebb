#include "airshape/geometry/bspline_patch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Mat.hxx>

namespace airshape::geometry {

std::optional<Patch> patchOf(const TopoDS_Face& face) {
  Patch patch;
  patch.surface = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));
  if (patch.surface.IsNull()) return std::nullopt;
  int wires = 0;
  for (TopExp_Explorer wire(face, TopAbs_WIRE); wire.More(); wire.Next()) ++wires;
  if (wires != 1) return std::nullopt;
  BRepTools::UVBounds(face, patch.u0, patch.u1, patch.v0, patch.v1);
  double su0, su1, sv0, sv1;
  patch.surface->Bounds(su0, su1, sv0, sv1);
  // The face is its whole surface: its boundary is the surface's four boundary curves.
  const double slack = 1e-9;
  if (std::abs(patch.u0 - su0) > slack * (su1 - su0) || std::abs(patch.u1 - su1) > slack * (su1 - su0) ||
      std::abs(patch.v0 - sv0) > slack * (sv1 - sv0) || std::abs(patch.v1 - sv1) > slack * (sv1 - sv0))
    return std::nullopt;
  return patch;
}

Bnd_Box poleBox(const Patch& patch) {
  Bnd_Box box;
  const TColgp_Array2OfPnt& poles = patch.surface->Poles();
  for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i)
    for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j) box.Add(poles(i, j));
  box.Enlarge(1e-6 * std::sqrt(box.SquareExtent()));
  return box;
}

namespace {

/// Where a curve C(s) (a line or a surface's curve) meets the patch, by Newton's method on
/// (u, v, s) with S(u, v) = C(s), from (point.u, point.v, s); s is held within [sLow, sHigh].
/// `curveAt(s, value, derivative)` evaluates the curve; `apartAllowed(curvePoint)` is how far
/// apart the two points may end without the curve missing the patch. The point's u, v, s and
/// point are set.
template <class CurveAt, class ApartAllowed>
bool meetOnPatch(const Patch& patch, double s, double sLow, double sHigh, const CurveAt& curveAt,
                 const ApartAllowed& apartAllowed, PatchPoint& point) {
  double u = point.u, v = point.v;
  const double uSpan = patch.u1 - patch.u0, vSpan = patch.v1 - patch.v0, sSpan = sHigh - sLow;
  for (int iteration = 0; iteration < 40; ++iteration) {
    gp_Pnt surfacePoint, curvePoint;
    gp_Vec du, dv, ds;
    patch.surface->D1(u, v, surfacePoint, du, dv);
    curveAt(s, curvePoint, ds);
    const gp_Mat jacobian(du.XYZ(), dv.XYZ(), ds.Reversed().XYZ());
    const double determinant = jacobian.Determinant();
    if (std::abs(determinant) < 1e-12 * du.Magnitude() * dv.Magnitude() * ds.Magnitude()) return false;
    gp_XYZ step = curvePoint.XYZ() - surfacePoint.XYZ();
    step.Multiply(jacobian.Inverted());
    // Held within the bounds; the moves taken, not the steps asked for, tell convergence (at a
    // bound the step may keep asking to leave by a rounding error).
    const double nextU = std::clamp(u + step.X(), patch.u0, patch.u1);
    const double nextV = std::clamp(v + step.Y(), patch.v0, patch.v1);
    const double nextS = std::clamp(s + step.Z(), sLow, sHigh);
    const bool settled = std::abs(nextU - u) <= 1e-13 * uSpan && std::abs(nextV - v) <= 1e-13 * vSpan &&
                         std::abs(nextS - s) <= 1e-13 * sSpan;
    u = nextU;
    v = nextV;
    s = nextS;
    if (settled) {
      surfacePoint = patch.surface->Value(u, v);
      curveAt(s, curvePoint, ds);
      if (surfacePoint.Distance(curvePoint) > apartAllowed(curvePoint))
        return false;  // held at a bound: it misses the patch
      point.u = u;
      point.v = v;
      point.s = s;
      point.point = surfacePoint;
      return true;
    }
  }
  return false;
}

}  // namespace

bool meetLine(const Patch& patch, const gp_Pnt& base, const gp_Vec& direction, PatchPoint& point) {
  // A line runs on without bounds: its s is never held, and never keeps it from settling.
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  const double s = gp_Vec(base, patch.surface->Value(point.u, point.v)).Dot(direction) / direction.SquareMagnitude();
  const auto lineAt = [&](double at, gp_Pnt& value, gp_Vec& along) {
    value = base.Translated(at * direction);
    along = direction;
  };
  const double apart = 1e-9 * (1.0 + gp_Vec(base.XYZ()).Magnitude() + direction.Magnitude());
  return meetOnPatch(
      patch, s, -kUnbounded, kUnbounded, lineAt, [apart](const gp_Pnt&) { return apart; }, point);
}

bool meetCurve(const Patch& patch, const Patch& curves, double fixed, bool alongU, PatchPoint& point) {
  const double sLow = alongU ? curves.u0 : curves.v0, sHigh = alongU ? curves.u1 : curves.v1;
  const auto curveAt = [&](double at, gp_Pnt& value, gp_Vec& along) {
    gp_Vec alongCurveU, alongCurveV;
    curves.surface->D1(alongU ? at : fixed, alongU ? fixed : at, value, alongCurveU, alongCurveV);
    along = alongU ? alongCurveU : alongCurveV;
  };
  const auto apartAllowed = [](const gp_Pnt& onCurve) { return 1e-9 * (1.0 + gp_Vec(onCurve.XYZ()).Magnitude()); };
  return meetOnPatch(patch, std::clamp(point.s, sLow, sHigh), sLow, sHigh, curveAt, apartAllowed, point);
}

std::optional<SkinPatches> skinPatches(const TopoDS_Shape& skin) {
  SkinPatches result;
  for (TopExp_Explorer face(skin, TopAbs_FACE); face.More(); face.Next()) {
    const auto patch = patchOf(TopoDS::Face(face.Current()));
    if (!patch) return std::nullopt;
    result.faces.push_back(TopoDS::Face(face.Current()));
    result.patches.push_back(*patch);
  }
  return result;
}

}  // namespace airshape::geometry
