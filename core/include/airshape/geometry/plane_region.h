#pragma once

#include <optional>
#include <vector>

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pln.hxx>

namespace airshape::geometry {

/// A curve of a plane: in space, and its image in the plane's own coordinates (the x and y
/// axes of the gp_Pln), over the same parameters.
struct PlaneCurve {
  Handle(Geom_BSplineCurve) curve;
  Handle(Geom2d_BSplineCurve) image;
};

/// A closed loop of curves joined end to end.
using PlaneLoop = std::vector<PlaneCurve>;

/// A region of a plane by its boundary: loops with the region on the left of each, seen from
/// the plane's normal (outer loops run counterclockwise, holes clockwise).
using PlaneRegion = std::vector<PlaneLoop>;

/// The curve put exactly into the plane (its poles projected onto it), with its image.
PlaneCurve planeCurve(const gp_Pln& plane, const Handle(Geom_BSplineCurve) & curve);

/// An edge's curve as a B-spline over the edge's range, running the way the edge does; null
/// for an edge without a curve in space.
Handle(Geom_BSplineCurve) edgeCurve(const TopoDS_Edge& edge);

/// A planar face's region: its wire, run so that the face lies on its left; nothing for a
/// face with holes.
std::optional<PlaneRegion> regionOf(const gp_Pln& plane, const TopoDS_Face& face);

/// The region inside a closed loop of curves of the plane joined end to end, run so that it
/// lies on the loop's left.
std::optional<PlaneRegion> regionInside(const gp_Pln& plane, const std::vector<Handle(Geom_BSplineCurve)>& curves);

/// The faces where two regions overlap (the Boolean common of two planar regions, without a
/// Boolean operation): each bounded by the pieces of either boundary that lie inside the
/// other, split where the boundaries cross; where the boundaries run together (a side two
/// faces of one surface share), followed once when both regions lie on the same side of it.
/// Empty when the regions do not overlap; nothing when this cannot tell: boundaries that touch
/// without crossing, or a common with a hole. `tolerance` is a length: how close points must
/// be to be one.
std::optional<std::vector<TopoDS_Face>> commonOf(const gp_Pln& plane, const PlaneRegion& a, const PlaneRegion& b,
                                                 double tolerance);

}  // namespace airshape::geometry
