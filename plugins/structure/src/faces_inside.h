#pragma once

#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::structure {

/// The parts of `faces` inside `solid` (a Boolean common whose face pairs are intersected on
/// every core); empty when nothing lies inside. Throws Error (which its caller gives a CPACS
/// path) when the common fails.
std::vector<TopoDS_Face> facesInside(const TopoDS_Shape& faces, const TopoDS_Shape& solid);

}  // namespace airshape::structure
