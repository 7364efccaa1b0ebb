#pragma once

#include <optional>
#include <vector>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

/// The edges where a shape whose faces are untrimmed B-spline patches or planes (a lifting surface)
/// meets a skin of untrimmed B-spline patches and planes (a body), found without
/// intersecting curved surfaces: each ruling of a ruled face (a lifting surface of straight segments), or
/// each v-curve of another face (a guided lifting surface's curves along its span), is met with the skin by
/// Newton's method, and the curve through those points is drawn in the skin face's own
/// parameters until it follows the crossing within `tolerance` (geometry/ruled_crossing.h). The
/// traced lines must close, and the plane faces (a lifting surface's root and tip, a body's end caps)
/// must be met nowhere. Nothing where this does not apply: a face that is none of these, a
/// ruling or curve that meets the skin at two points or tangentially, a line that does not
/// close (it goes on over a plane face), a plane face met inside: the caller then takes OCCT's
/// Boolean section.
std::optional<std::vector<TopoDS_Edge>> tracedSection(const TopoDS_Shape& ruled, const TopoDS_Shape& skin,
                                                      double tolerance);

}  // namespace airshape::geometry
