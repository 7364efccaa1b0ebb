#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape::geometry {

/// A closed loop of ruled sides across a skin (global axes): side k joins the line through
/// `points[k]` along `directions[k]` to the line through the next point along the next
/// direction (the lines between them interpolated linearly), as the sides of a prism whose
/// outline is the loop. `rays`: only the half-lines from the points along the directions count
/// (rays from inside a closed body).
struct RuledLoop {
  std::vector<gp_Pnt> points;
  std::vector<gp_Vec> directions;
  bool rays = false;
};

/// The faces of `skin` split along where the loop's sides cross it, made without intersecting
/// surfaces: each side's lines are met with the skin's faces by Newton's method, the curve
/// through those points is drawn in each face's own parameters (so that it lies on the face,
/// within `tolerance` of the true crossing of side and skin) and the faces are rebuilt along
/// those curves (faces the loop does not touch as they are). Where a side runs beyond the
/// skin's edge, the pieces follow that edge. Nothing when the skin is not what this handles
/// (faces that are not untrimmed B-spline patches, a line that meets the skin twice, a crossing
/// the curves cannot follow): the caller then cuts the skin by a Boolean operation.
std::optional<std::vector<TopoDS_Face>> skinSplitByLoop(const TopoDS_Shape& skin, const RuledLoop& loop,
                                                        double tolerance);

/// The pieces of the split skin (skinSplitByLoop) a point inside which passes `keep` (global
/// axes); nothing where the split does not apply.
std::optional<std::vector<TopoDS_Face>> skinPiecesWhere(const TopoDS_Shape& skin, const RuledLoop& loop,
                                                        const std::function<bool(const gp_Pnt&)>& keep,
                                                        double tolerance);

}  // namespace airshape::geometry
