#pragma once

#include <Bnd_Box.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/query/query_registry.h"

namespace airshape::query {

/// The tight box of a shape, from its exact geometry (not its control points).
Bnd_Box tightBox(const TopoDS_Shape& shape);

/// A box as the protocol answers it: {"min": [x, y, z], "max": [x, y, z]}.
Json boxAnswer(const Bnd_Box& box);

}  // namespace airshape::query
