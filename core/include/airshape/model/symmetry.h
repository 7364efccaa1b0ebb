#pragma once

#include <string>

namespace airshape {
class Configuration;
}

namespace airshape::model {

/// The mirror plane of a component after inheritance: "x-y", "x-z", "y-z" or "none".
/// A missing symmetry attribute, or "inherit", takes the parent's (through parentUID,
/// recursively); with no parent it is "none"; an unknown value means "none".
std::string resolvedSymmetry(const Configuration& configuration, const std::string& componentUid);

}  // namespace airshape::model
