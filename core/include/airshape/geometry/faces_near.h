#pragma once

#include <vector>

#include <Bnd_Box.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

/// A region of space as boxes (of another shape's faces, say).
using Region = std::vector<Bnd_Box>;

/// The faces of `shape` that may reach into `region`, as a compound: a face that fills a
/// parameter rectangle of a B-spline surface is cut down to the knot spans whose poles reach
/// into one of the region's boxes (the same surface over fewer spans, the same parameters), a face whose box
/// misses them is left out, any other face is kept whole. What a Boolean section needs
/// of a large skin where a small part meets it: OCCT samples a face pair over both faces'
/// whole parameter ranges, seconds a pair for a revolved cowl of 600 × 30 spans.
TopoDS_Shape facesNear(const TopoDS_Shape& shape, const Region& region);

}  // namespace airshape::geometry
