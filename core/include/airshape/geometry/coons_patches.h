#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include "airshape/geometry/curve_network.h"

namespace airshape::geometry {

/// How a patch blends its four boundaries into its inside.
enum class PatchBlending {
  Bilinear,  ///< linear across (a bilinearly blended Coons patch; OCCT's stretch style)
  Rounded,   ///< with 3t² − 2t³ across (OCCT's Coons style)
};

/// The skin through a curve network of open profiles and guides built the way the
/// reference library builds its skins with guide curves: one patch per cell (the region
/// bounded by two neighbouring profiles and two neighbouring guides), each OCCT's filling
/// (GeomFill_BSplineCurves) of the four boundary pieces, each piece parametrised over
/// [0, 1] by its own curve's parameter. Neighbouring patches meet with position continuity
/// only. `blending(k, l)` chooses the blending of cell l of row k.
///
/// Returns one surface per pair of neighbouring profiles ("row" k between profile k and
/// k+1): its cells side by side in u, cell l (between guide l and l+1) over u ∈ [l, l+1],
/// and v ∈ [0, 1] from profile k to profile k+1, linear in the guides' own parameter.
/// `crossings` say where guide l meets profile k: profileParameters(k, l) ascending in l,
/// guideParameters(k, l) ascending in k. Closed profiles close the ring of cells with a
/// last guide that repeats the first, its profile parameters one period on (past the
/// curves' ends, where the pieces continue from the start). Throws Error when a cell
/// cannot be filled, naming it as `describe(k, l)` does (by default "the cell between
/// profiles k+1 and k+2 and guides l+1 and l+2"; a caller names its own curves).
std::vector<Handle(Geom_BSplineSurface)> buildCoonsPatchRows(
    const std::vector<Handle(Geom_BSplineCurve)>& profiles, const std::vector<Handle(Geom_BSplineCurve)>& guides,
    const KnownCrossings& crossings, const std::function<PatchBlending(std::size_t row, std::size_t cell)>& blending,
    const std::function<std::string(std::size_t row, std::size_t cell)>& describe = {});

/// One Coons patch from four boundary curves: `bottom` and `top` run the same way (u),
/// `left` and `right` run from bottom to top (v); the corners must meet. The patch spans
/// [0, 1] × [0, 1] with patch(u, 0) on bottom, patch(u, 1) on top, patch(0, v) on left and
/// patch(1, v) on right, each at its normalised parameter.
Handle(Geom_BSplineSurface)
    coonsPatch(Handle(Geom_BSplineCurve) bottom, Handle(Geom_BSplineCurve) right, Handle(Geom_BSplineCurve) top,
               Handle(Geom_BSplineCurve) left, PatchBlending blending);

}  // namespace airshape::geometry
