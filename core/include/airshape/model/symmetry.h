#pragma once

#include <string>

#include <gp_Trsf.hxx>

namespace airshape {
class Configuration;
}

namespace airshape::model {

/// The mirror plane of a component after inheritance: "x-y", "x-z", "y-z" or "none".
/// A missing symmetry attribute, or "inherit", takes the parent's (through parentUID,
/// recursively); with no parent it is "none"; an unknown value means "none".
std::string resolvedSymmetry(const Configuration& configuration, const std::string& componentUid);

/// The mirror in a plane through the origin named as resolvedSymmetry() names it ("x-y",
/// "x-z" or "y-z").
gp_Trsf mirrorIn(const std::string& plane);

}  // namespace airshape::model
