#include <chrono>
#include <iomanip>
#include <iostream>

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

/// Builds one component's solid and says how that went, in one line.
bool buildOne(const Configuration& configuration, const graph::Component& component) {
  std::cout << "  " << std::left << std::setw(10) << component.nodeType << ' ' << std::setw(32) << component.uid << ' ';
  if (configuration.shapes().find(component.nodeType) == nullptr) {
    std::cout << "no builder yet\n";
    return true;
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    const TopoDS_Shape solid = configuration.shapes().shapeOf(configuration, component.uid);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool valid = BRepCheck_Analyzer(solid).IsValid();
    std::cout << (valid ? "valid solid" : "INVALID solid") << ", volume " << geometry::volumeOf(solid) << ", "
              << std::fixed << std::setprecision(3) << seconds << " s\n"
              << std::defaultfloat << std::setprecision(6);
    return valid;
  } catch (const Error& error) {
    std::cout << "FAILED: " << error.what() << '\n';
  } catch (const Standard_Failure& failure) {
    std::cout << "FAILED: geometry kernel failure: " << failure.GetMessageString() << '\n';
  }
  return false;
}

}  // namespace

int runBuild(const Arguments& arguments, plugin::PluginHost& host) {
  const std::string path = singleFileArgument(arguments, "build");
  const Configuration configuration = openConfiguration(path, host);
  const graph::ComponentGraph& graph = configuration.components();
  std::cout << path << ": building " << graph.components().size() << " components\n";
  bool allGood = true;
  for (std::size_t index : graph.buildOrder()) allGood = buildOne(configuration, graph.components()[index]) && allGood;
  return allGood ? kSuccess : kProblemsFound;
}

}  // namespace airshape::cli
