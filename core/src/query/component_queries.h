#pragma once

#include "airshape/query/query_registry.h"

namespace airshape::query {

/// The component ops of the query protocol's second part (QUERY-components §2) that every
/// component answers through the shape its plugin builds: component_type, component_volume,
/// component_surface_area, cross_section_area, intersection_count and intersection_length.
void registerComponentQueries(QueryRegistry& registry);

}  // namespace airshape::query
