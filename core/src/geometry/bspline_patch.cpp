#include "airshape/geometry/bspline_patch.h"

#include <algorithm>
#include <cmath>

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

bool meetLine(const Patch& patch, const gp_Pnt& base, const gp_Vec& direction, PatchPoint& point) {
  double u = point.u, v = point.v;
  double s = gp_Vec(base, patch.surface->Value(u, v)).Dot(direction) / direction.SquareMagnitude();
  const double uSpan = patch.u1 - patch.u0, vSpan = patch.v1 - patch.v0;
  for (int iteration = 0; iteration < 40; ++iteration) {
    gp_Pnt surfacePoint;
    gp_Vec du, dv;
    patch.surface->D1(u, v, surfacePoint, du, dv);
    const gp_Mat jacobian(du.XYZ(), dv.XYZ(), direction.Reversed().XYZ());
    const double determinant = jacobian.Determinant();
    if (std::abs(determinant) < 1e-12 * du.Magnitude() * dv.Magnitude() * direction.Magnitude()) return false;
    gp_XYZ step = base.XYZ() + s * direction.XYZ() - surfacePoint.XYZ();
    step.Multiply(jacobian.Inverted());
    // Held within the patch; the moves taken, not the steps asked for, tell convergence (at a
    // bound the step may keep asking to leave by a rounding error).
    const double nextU = std::clamp(u + step.X(), patch.u0, patch.u1);
    const double nextV = std::clamp(v + step.Y(), patch.v0, patch.v1);
    const bool settled = std::abs(nextU - u) <= 1e-13 * uSpan && std::abs(nextV - v) <= 1e-13 * vSpan;
    u = nextU;
    v = nextV;
    s += step.Z();
    if (settled) {
      surfacePoint = patch.surface->Value(u, v);
      const gp_Pnt onLine = base.Translated(s * direction);
      if (surfacePoint.Distance(onLine) > 1e-9 * (1.0 + gp_Vec(base.XYZ()).Magnitude() + direction.Magnitude()))
        return false;  // held at a bound: the line misses the patch
      point.u = u;
      point.v = v;
      point.point = surfacePoint;
      return true;
    }
  }
  return false;
}

bool meetCurve(const Patch& patch, const Patch& curves, double fixed, bool alongU, PatchPoint& point) {
  const double sLow = alongU ? curves.u0 : curves.v0, sHigh = alongU ? curves.u1 : curves.v1;
  double a = point.u, b = point.v, s = std::clamp(point.s, sLow, sHigh);
  const double aSpan = patch.u1 - patch.u0, bSpan = patch.v1 - patch.v0, sSpan = sHigh - sLow;
  const auto curveAt = [&](double at, gp_Pnt& value, gp_Vec& along) {
    gp_Vec du, dv;
    curves.surface->D1(alongU ? at : fixed, alongU ? fixed : at, value, du, dv);
    along = alongU ? du : dv;
  };
  for (int iteration = 0; iteration < 40; ++iteration) {
    gp_Pnt surfacePoint, curvePoint;
    gp_Vec da, db, ds;
    patch.surface->D1(a, b, surfacePoint, da, db);
    curveAt(s, curvePoint, ds);
    const gp_Mat jacobian(da.XYZ(), db.XYZ(), ds.Reversed().XYZ());
    const double determinant = jacobian.Determinant();
    if (std::abs(determinant) < 1e-12 * da.Magnitude() * db.Magnitude() * ds.Magnitude()) return false;
    gp_XYZ step = curvePoint.XYZ() - surfacePoint.XYZ();
    step.Multiply(jacobian.Inverted());
    // Held within both bounds; the moves taken tell convergence, as for a line.
    const double nextA = std::clamp(a + step.X(), patch.u0, patch.u1);
    const double nextB = std::clamp(b + step.Y(), patch.v0, patch.v1);
    const double nextS = std::clamp(s + step.Z(), sLow, sHigh);
    const bool settled = std::abs(nextA - a) <= 1e-13 * aSpan && std::abs(nextB - b) <= 1e-13 * bSpan &&
                         std::abs(nextS - s) <= 1e-13 * sSpan;
    a = nextA;
    b = nextB;
    s = nextS;
    if (settled) {
      surfacePoint = patch.surface->Value(a, b);
      curveAt(s, curvePoint, ds);
      if (surfacePoint.Distance(curvePoint) > 1e-9 * (1.0 + gp_Vec(curvePoint.XYZ()).Magnitude()))
        return false;  // held at a bound: the curve misses the patch
      point.u = a;
      point.v = b;
      point.s = s;
      point.point = surfacePoint;
      return true;
    }
  }
  return false;
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
