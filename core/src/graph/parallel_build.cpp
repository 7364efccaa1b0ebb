#include "airshape/graph/parallel_build.h"

#include <map>

#include "airshape/parallel_for.h"

namespace airshape::graph {

void forEachByDepth(const ComponentGraph& graph, const std::vector<std::size_t>& indices,
                    const std::function<void(std::size_t index)>& task) {
  std::map<std::size_t, std::vector<std::size_t>> byDepth;
  for (std::size_t index : indices) byDepth[graph.depth(index)].push_back(index);
  for (const auto& [depth, atDepth] : byDepth)
    parallelFor(atDepth.size(), [&task, &level = atDepth](std::size_t i) { task(level[i]); });
}

}  // namespace airshape::graph
