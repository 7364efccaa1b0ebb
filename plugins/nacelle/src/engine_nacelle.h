#pragma once

#include <string>

#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// The nacelle of an engine placement (`engines/engine` of a model; QUERY-components §1,
/// `engine_nacelle`; docs/nacelle.md): the fan cowl and, where the engine has them, the core
/// cowl and the centre cowl of the engine it references (`vehicles/engines/engine/nacelle`),
/// each a solid, moved by the placement's transformation (with its parent's translation). Faces
/// are named "<uID>/fan cowl", "<uID>/core cowl" and "<uID>/centre cowl". An engine without a
/// nacelle has no shape: Error.
NamedShape engineNacelle(const Configuration& configuration, const std::string& placementUid);

}  // namespace airshape::nacelle
