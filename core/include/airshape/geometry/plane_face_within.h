#pragma once

#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

namespace airshape::geometry {

/// A face of a plane bounded by a closed wire that may leave the plane (a riffled stiffener's line
/// round a plate at its mean station): the face is the part of the plane inside the wire
/// seen along the plane's normal, each edge keeping its own course in space, its curve on the
/// plane the orthogonal projection of that course and its tolerance the farthest it strays from
/// the plane, so that the face is valid. Its area is the area inside the projected wire; its box
/// holds the wire. The wire is copied; throws Error when it is open or bounds nothing.
TopoDS_Face planeFaceWithin(const gp_Pln& plane, const TopoDS_Wire& wire);

}  // namespace airshape::geometry
