#pragma once

#include <vector>

#include "airshape/named_shape.h"

namespace airshape {

/// The Boolean union of named solids, each face of the result named as the face it came
/// from (faces split by the union keep the name on every piece; faces inside the union
/// disappear). Throws Error when the union fails or is not a valid shape.
NamedShape fuseNamedShapes(const std::vector<const NamedShape*>& shapes);

/// A named solid with `tool` cut out of it (one Boolean cut), each face of the result named as
/// the face it came from: the argument's faces keep their names, the walls the tool leaves
/// take the tool's. Throws Error when the cut fails.
NamedShape cutNamedShape(const NamedShape& argument, const NamedShape& tool);

}  // namespace airshape
