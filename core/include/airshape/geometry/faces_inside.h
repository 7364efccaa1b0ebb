#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

/// The parts of `faces` inside `solid` (a Boolean common whose face pairs are intersected on
/// every core); empty when nothing lies inside. Throws Error (which its caller gives a CPACS
/// path) when the common fails.
std::vector<TopoDS_Face> facesInside(const TopoDS_Shape& faces, const TopoDS_Shape& solid);

/// For each face, its parts inside `solid`, found by one Boolean common for all of them (much
/// faster than one each: the solid is prepared once). Throws Error when the common fails.
std::vector<std::vector<TopoDS_Face>> facesInsideEach(const std::vector<TopoDS_Face>& faces, const TopoDS_Shape& solid);

/// For each face, the pieces `direct` makes of it without a Boolean operation (a section traced
/// from the skins), or, where it makes none, its parts inside the solid `solid` gives (asked for
/// only then: building it may cost more than the pieces): one Boolean common for all of those.
/// Throws Error when the common fails.
std::vector<std::vector<TopoDS_Face>> facesInsideEach(
    const std::vector<TopoDS_Face>& faces, const std::function<const TopoDS_Shape&()>& solid,
    const std::function<std::optional<std::vector<TopoDS_Face>>(std::size_t index)>& direct);

}  // namespace airshape::geometry
