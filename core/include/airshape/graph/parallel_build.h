#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "airshape/graph/component_graph.h"

namespace airshape::graph {

/// Runs `task` once for each component index in `indices`, parents before children:
/// components at one depth of the graph do not depend on each other and run in parallel,
/// at most one per processor at a time, each processor taking the next as it finishes one.
/// `task` must not throw.
void forEachByDepth(const ComponentGraph& graph, const std::vector<std::size_t>& indices,
                    const std::function<void(std::size_t index)>& task);

}  // namespace airshape::graph
