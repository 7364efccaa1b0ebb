#include "airshape/geometry/faces_near.h"

#include <algorithm>
#include <optional>
#include <vector>

#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <BSplCLib.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/geometry/loft_piece.h"
#include "rectangular_patch.h"

namespace airshape::geometry {

namespace {

/// Whether a box meets one of the region's.
bool meets(const Bnd_Box& box, const Region& region) {
  return std::any_of(region.begin(), region.end(), [&](const Bnd_Box& part) { return !box.IsOut(part); });
}

/// The first pole (0-based, before wrapping round a periodic surface) of each span between
/// `breaks`, along u or along v: the span's points depend on it and the degree's next ones.
std::vector<int> firstPoles(const Geom_BSplineSurface& surface, bool alongU, const std::vector<double>& breaks) {
  const int degree = alongU ? surface.UDegree() : surface.VDegree();
  const bool periodic = alongU ? surface.IsUPeriodic() : surface.IsVPeriodic();
  TColStd_Array1OfInteger multiplicities(1, alongU ? surface.NbUKnots() : surface.NbVKnots());
  alongU ? surface.UMultiplicities(multiplicities) : surface.VMultiplicities(multiplicities);
  std::vector<int> first;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double middle = 0.5 * (breaks[i] + breaks[i + 1]);
    int knot = 0, next = 0;
    alongU ? surface.LocateU(middle, 0.0, knot, next) : surface.LocateV(middle, 0.0, knot, next);
    first.push_back(BSplCLib::PoleIndex(degree, knot, periodic, multiplicities));
  }
  return first;
}

/// The box of the poles a span depends on.
Bnd_Box spanPoleBox(const Geom_BSplineSurface& surface, int firstU, int firstV) {
  Bnd_Box box;
  for (int i = 0; i <= surface.UDegree(); ++i)
    for (int j = 0; j <= surface.VDegree(); ++j)
      box.Add(surface.Pole((firstU + i) % surface.NbUPoles() + 1, (firstV + j) % surface.NbVPoles() + 1));
  return box;
}

/// The part of a B-spline patch whose spans' poles reach into the region; the face itself
/// where that is all of it, nothing where it is none.
std::optional<TopoDS_Face> partNear(const TopoDS_Face& face, const RectangularPatch& patch,
                                    const Handle(Geom_BSplineSurface) & surface, const Region& region) {
  const std::vector<int> uFirst = firstPoles(*surface, true, patch.uBreaks);
  const std::vector<int> vFirst = firstPoles(*surface, false, patch.vBreaks);
  std::size_t uLow = uFirst.size(), uHigh = 0, vLow = vFirst.size(), vHigh = 0;
  for (std::size_t i = 0; i < uFirst.size(); ++i)
    for (std::size_t j = 0; j < vFirst.size(); ++j)
      if (meets(spanPoleBox(*surface, uFirst[i], vFirst[j]), region)) {
        uLow = std::min(uLow, i), uHigh = std::max(uHigh, i + 1);
        vLow = std::min(vLow, j), vHigh = std::max(vHigh, j + 1);
      }
  if (uLow >= uHigh) return std::nullopt;
  if (uLow == 0 && vLow == 0 && uHigh == uFirst.size() && vHigh == vFirst.size()) return face;
  TopoDS_Face part =
      surfacePartFace(surface, patch.uBreaks[uLow], patch.uBreaks[uHigh], patch.vBreaks[vLow], patch.vBreaks[vHigh]);
  part.Orientation(face.Orientation());
  return part;
}

}  // namespace

TopoDS_Shape facesNear(const TopoDS_Shape& shape, const Region& region) {
  BRep_Builder builder;
  TopoDS_Compound near;
  builder.MakeCompound(near);
  for (TopExp_Explorer explorer(shape, TopAbs_FACE); explorer.More(); explorer.Next()) {
    const TopoDS_Face& face = TopoDS::Face(explorer.Current());
    Bnd_Box box;
    BRepBndLib::Add(face, box, false);
    if (!meets(box, region)) continue;
    const std::optional<RectangularPatch> patch = rectangularPatch(face);
    const auto surface = patch ? Handle(Geom_BSplineSurface)::DownCast(patch->surface) : nullptr;
    if (surface.IsNull()) {
      builder.Add(near, face);
    } else if (const std::optional<TopoDS_Face> part = partNear(face, *patch, surface, region)) {
      builder.Add(near, *part);
    }
  }
  return near;
}

}  // namespace airshape::geometry
