#pragma once

#include <vector>

#include <TopoDS_Shape.hxx>
#include <gp_Lin.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape::controlsurfaces {

/// Where an infinite line meets the faces of a shape.
struct LineCrossing {
  double along;  ///< the line's parameter (distance from its origin, signed)
  gp_Pnt point;
  gp_Vec normal;  ///< the face's normal there (not normalised, orientation of its surface)
};

/// Every crossing of `line` with `shape`, ordered along the line; a line through an edge
/// between two faces crosses once (crossings closer than `merge` are one).
std::vector<LineCrossing> crossingsOf(const TopoDS_Shape& shape, const gp_Lin& line, double merge);

/// The point of `shape` nearest to `line` within `reach` of its origin (where the line meets
/// the shape, if it does); of several equally near, the one nearest the line's origin.
/// Throws Error when the shape is empty.
gp_Pnt nearestToLine(const TopoDS_Shape& shape, const gp_Lin& line, double reach);

}  // namespace airshape::controlsurfaces
