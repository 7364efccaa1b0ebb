#pragma once

#include <optional>
#include <vector>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

/// The lines along which a plane face of one shape touches a curved face of the other without
/// the two crossing (a root laid on a body's side, which is tangent to it), both ways
/// round: where an untrimmed B-spline patch lies on one side of the face's plane and reaches it
/// within `tolerance` along a curve, the part of that curve inside the face. A section of the two
/// surfaces misses such lines, or finds bits of them, since the surfaces meet without crossing.
/// Isolated points of contact give no line.
///
/// Returns the section's `edges` with those lines added and the edges that lie in such a contact
/// (on both touching faces: pieces of it, or the same line found a little apart, as the surfaces
/// are within the tolerance of each other across a band) taken out; nothing where the shapes
/// touch along no line.
std::optional<std::vector<TopoDS_Edge>> withTangentContacts(const std::vector<TopoDS_Edge>& edges,
                                                            const TopoDS_Shape& first, const TopoDS_Shape& second,
                                                            double tolerance);

}  // namespace airshape::geometry
