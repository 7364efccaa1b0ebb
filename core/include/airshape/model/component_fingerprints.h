#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>

namespace airshape {
class Configuration;
}

namespace airshape::model {

/// A hash per component (by uID) of everything its geometry is read from: its element with
/// all it holds, and the elements its uIDrefs point to outside it (airfoils, profiles,
/// guide-curve profiles, its parent). Two fingerprints differ when an edit can
/// change the component's geometry.
std::map<std::string, std::uint64_t> componentFingerprints(const Configuration& configuration);

/// The components whose fingerprint changed between `before` and `after` (new and removed
/// ones included), with every component attached below them through parentUID: a moved
/// component moves those hanging from it.
std::set<std::string> changedComponents(const Configuration& configuration,
                                        const std::map<std::string, std::uint64_t>& before,
                                        const std::map<std::string, std::uint64_t>& after);

}  // namespace airshape::model
