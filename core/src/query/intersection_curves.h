#pragma once

#include <optional>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include "airshape/query/query_registry.h"

namespace airshape {
class Configuration;
}

namespace airshape::query {

/// The op `intersection_curves`: where the solids of two components meet (a lifting surface and a
/// body at their junction), as polylines: {"uid": A, "other": B, ["other_mirrored": true],
/// ["deflection": metres]} -> [[[x, y, z], ...], ...], one polyline per connected piece of
/// the intersection, its points no farther than `deflection` (default 1 mm) from the
/// exact curve. Two components that do not meet give [].
Json intersectionCurves(Configuration& configuration, const Json& query);

/// Where two shapes' boundaries meet (OCCT's section with approximated curves), its edges
/// chained into lines: maximal runs of edges sharing end points, each line kept once.
/// `names` says what was intersected, for the error when OCCT cannot compute it.
std::vector<TopoDS_Wire> intersectionLines(const TopoDS_Shape& first, const TopoDS_Shape& second,
                                           const std::string& names);

/// The closed lines where a plane cuts a shape (OCCT's section with approximated curves,
/// chained); nothing when OCCT fails or a line does not close (the plane touches the shape, or
/// leaves a gap between two faces' curves).
std::optional<std::vector<TopoDS_Wire>> planeSectionLoops(const TopoDS_Shape& shape, const gp_Pln& plane);

}  // namespace airshape::query
