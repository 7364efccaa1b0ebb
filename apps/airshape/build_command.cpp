#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <BRepCheck_Analyzer.hxx>
#include <Standard_Failure.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/graph/parallel_build.h"
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

/// Builds every component, independent ones in parallel.
std::vector<BuildReport> buildAll(const Configuration& configuration) {
  const graph::ComponentGraph& graph = configuration.components();
  std::vector<BuildReport> reports(graph.components().size());
  graph::forEachByDepth(graph, graph.buildOrder(), [&](std::size_t index) {
    reports[index] = buildOne(configuration, graph.components()[index]);
  });
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
