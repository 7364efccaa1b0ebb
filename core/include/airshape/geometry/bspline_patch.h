#pragma once

#include <optional>
#include <vector>

#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape::geometry {

/// A skin face as the direct constructions from the skins use it: an untrimmed B-spline patch,
/// the face being its whole surface.
struct Patch {
  Handle(Geom_BSplineSurface) surface;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

/// A point of a patch on a line: the line's parameter, the patch parameters and the point;
/// `s`, where a curve rather than a line meets the patch, the curve's own parameter there.
struct PatchPoint {
  double t = 0, u = 0, v = 0;
  gp_Pnt point;
  double s = 0;
};

/// The face as a patch; nothing when it is not a B-spline surface bounded by its own four
/// boundary curves.
std::optional<Patch> patchOf(const TopoDS_Face& face);

/// A box round the patch's poles, which hold the whole surface (convex hull property): a line
/// or a shape that misses it misses the patch.
Bnd_Box poleBox(const Patch& patch);

/// A skin's faces and their patches, in the order the skin holds them.
struct SkinPatches {
  std::vector<TopoDS_Face> faces;
  std::vector<Patch> patches;
};

/// The skin's faces as patches; nothing when one is not an untrimmed B-spline patch.
std::optional<SkinPatches> skinPatches(const TopoDS_Shape& skin);

/// The point where the line through `base` along `direction` meets the patch, by Newton's
/// method on (u, v, s) with S(u, v) = base + s * direction, from the guess in `point` (its u
/// and v). False where the line meets the patch tangentially or not within its bounds.
bool meetLine(const Patch& patch, const gp_Pnt& base, const gp_Vec& direction, PatchPoint& point);

/// The point where a curve of `curves` meets the patch: its v-curve at u = `fixed`, or with
/// `alongU` its u-curve at v = `fixed`, s being the curve's own parameter. By Newton's method on
/// (u, v, s) with S(u, v) = C(s), from the guess in `point` (its u, v and s). False where it
/// meets the patch tangentially or not within their bounds.
bool meetCurve(const Patch& patch, const Patch& curves, double fixed, bool alongU, PatchPoint& point);

}  // namespace airshape::geometry
