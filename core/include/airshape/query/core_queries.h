#pragma once

#include "airshape/query/query_registry.h"

namespace airshape::query {

/// Registers the ops the core answers itself, for any component type (bounding_box).
void registerCoreQueries(QueryRegistry& registry);

}  // namespace airshape::query
