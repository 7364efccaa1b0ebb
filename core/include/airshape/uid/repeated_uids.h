#pragma once

#include "airshape/schema/node.h"
#include "airshape/uid/uid_registry.h"

namespace airshape::uid {

/// Takes every node whose uID was defined earlier in the document out of the model (the first
/// definition wins), so that geometry sees each uID once. The document keeps those elements:
/// they are set aside in their parent and saved unchanged. Returns how many were set aside.
std::size_t setAsideRepeatedUids(schema::Node& root, const UidRegistry& registry);

}  // namespace airshape::uid
