#include <algorithm>
#include <chrono>
#include <future>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <BRepCheck_Analyzer.hxx>
#include <Standard_Failure.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

namespace {

/// What building one component came to: its report line and whether it is a valid solid.
struct BuildReport {
  std::string line;
  bool good = false;
};

/// Builds one component's solid and checks it (BRepCheck, volume).
BuildReport buildOne(const Configuration& configuration, const graph::Component& component) {
  std::ostringstream line;
  line << "  " << std::left << std::setw(10) << component.nodeType << ' ' << std::setw(32) << component.uid << ' ';
  if (configuration.shapes().find(component.nodeType) == nullptr) return {line.str() + "no builder yet", true};
  const auto start = std::chrono::steady_clock::now();
  try {
    const TopoDS_Shape& solid = configuration.shapes().shapeOf(configuration, component.uid);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool valid = BRepCheck_Analyzer(solid).IsValid();
    line << (valid ? "valid solid" : "INVALID solid") << ", volume " << geometry::volumeOf(solid) << ", " << std::fixed
         << std::setprecision(3) << seconds << " s";
    return {line.str(), valid};
  } catch (const Error& error) {
    line << "FAILED: " << error.what();
  } catch (const Standard_Failure& failure) {
    line << "FAILED: geometry kernel failure: " << failure.GetMessageString();
  }
  return {line.str(), false};
}

/// Builds the components in dependency order, those at one depth of the graph (which do
/// not depend on each other) in parallel, at most one per processor at a time.
std::vector<BuildReport> buildAll(const Configuration& configuration) {
  const graph::ComponentGraph& graph = configuration.components();
  std::map<std::size_t, std::vector<std::size_t>> byDepth;
  for (std::size_t index : graph.buildOrder()) byDepth[graph.depth(index)].push_back(index);
  const std::size_t workers = std::max(1u, std::thread::hardware_concurrency());
  std::vector<BuildReport> reports(graph.components().size());
  for (const auto& [depth, indices] : byDepth)
    for (std::size_t first = 0; first < indices.size(); first += workers) {
      std::vector<std::future<BuildReport>> running;
      for (std::size_t i = first; i < std::min(indices.size(), first + workers); ++i)
        running.push_back(std::async(std::launch::async, buildOne, std::cref(configuration),
                                     std::cref(graph.components()[indices[i]])));
      for (std::size_t i = first; i < std::min(indices.size(), first + workers); ++i)
        reports[indices[i]] = running[i - first].get();
    }
  return reports;
}

}  // namespace

int runBuild(const Arguments& arguments, plugin::PluginHost& host) {
  const std::string path = singleFileArgument(arguments, "build");
  const Configuration configuration = openConfiguration(path, host);
  const graph::ComponentGraph& graph = configuration.components();
  std::cout << path << ": building " << graph.components().size() << " components\n";
  const std::vector<BuildReport> reports = buildAll(configuration);
  bool allGood = true;
  for (std::size_t index : graph.buildOrder()) {
    std::cout << reports[index].line << '\n';
    allGood = reports[index].good && allGood;
  }
  return allGood ? kSuccess : kProblemsFound;
}

}  // namespace airshape::cli
