#pragma once

#include <memory>
#include <vector>

#include <IntCurvesFace_ShapeIntersector.hxx>

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

/// Where lines meet one shape's faces, the shape prepared once for all of them (when the first
/// line is met): preparing OCCT's intersector for each face costs more than meeting one line
/// with it. Not to be shared between threads.
class LineCrossings {
 public:
  explicit LineCrossings(const TopoDS_Shape& shape);
  ~LineCrossings();
  LineCrossings(const LineCrossings&) = delete;
  LineCrossings& operator=(const LineCrossings&) = delete;

  /// Every crossing of `line` with the shape, ordered along the line; a line through an edge
  /// between two faces crosses once (crossings closer than `merge` are one).
  std::vector<LineCrossing> of(const gp_Lin& line, double merge);
  const TopoDS_Shape& shape() const { return shape_; }

 private:
  TopoDS_Shape shape_;
  std::unique_ptr<IntCurvesFace_ShapeIntersector> intersector_;
};

/// Every crossing of `line` with `shape` (LineCrossings::of, for one line).
std::vector<LineCrossing> crossingsOf(const TopoDS_Shape& shape, const gp_Lin& line, double merge);

/// The point of `shape` nearest to `line` within `reach` of its origin (where the line meets
/// the shape, if it does); of several equally near, the one nearest the line's origin.
/// Throws Error when the shape is empty.
gp_Pnt nearestToLine(const TopoDS_Shape& shape, const gp_Lin& line, double reach);

}  // namespace airshape::controlsurfaces
