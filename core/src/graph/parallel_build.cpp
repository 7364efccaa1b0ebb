#include "airshape/graph/parallel_build.h"

#include <algorithm>
#include <future>
#include <map>
#include <thread>

namespace airshape::graph {

void forEachByDepth(const ComponentGraph& graph, const std::vector<std::size_t>& indices,
                    const std::function<void(std::size_t index)>& task) {
  std::map<std::size_t, std::vector<std::size_t>> byDepth;
  for (std::size_t index : indices) byDepth[graph.depth(index)].push_back(index);
  const std::size_t workers = std::max(1u, std::thread::hardware_concurrency());
  for (const auto& [depth, atDepth] : byDepth)
    for (std::size_t first = 0; first < atDepth.size(); first += workers) {
      std::vector<std::future<void>> running;
      for (std::size_t i = first; i < std::min(atDepth.size(), first + workers); ++i)
        running.push_back(std::async(std::launch::async, task, atDepth[i]));
      for (auto& job : running) job.get();
    }
}

}  // namespace airshape::graph
