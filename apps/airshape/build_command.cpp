#include <cctype>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>

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

/// A BRepCheck status in words: BRepCheck_SelfIntersectingWire -> "self intersecting wire".
std::string inWords(BRepCheck_Status status) {
  std::ostringstream name;
  BRepCheck::Print(status, name);
  const std::string printed = name.str();
  std::string words;
  for (char c : printed.substr(printed.find('_') + 1)) {
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    if (std::isupper(static_cast<unsigned char>(c)) && !words.empty()) words += ' ';
    words += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return words;
}

/// What BRepCheck finds wrong with a shape or any of its parts, each flaw once.
std::string flawsOf(const TopoDS_Shape& shape, const BRepCheck_Analyzer& analyzer) {
  std::set<std::string> flaws;
  auto add = [&](const BRepCheck_ListOfStatus& statuses) {
    for (BRepCheck_ListIteratorOfListOfStatus it(statuses); it.More(); it.Next())
      if (it.Value() != BRepCheck_NoError) flaws.insert(inWords(it.Value()));
  };
  for (const TopAbs_ShapeEnum type : {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_WIRE, TopAbs_FACE, TopAbs_SHELL, TopAbs_SOLID})
    for (TopExp_Explorer parts(shape, type); parts.More(); parts.Next()) {
      const Handle(BRepCheck_Result)& result = analyzer.Result(parts.Current());
      if (result.IsNull()) continue;
      add(result->Status());
      for (result->InitContextIterator(); result->MoreShapeInContext(); result->NextShapeInContext())
        add(result->StatusOnShape());
    }
  std::string text;
  for (const std::string& flaw : flaws) text += (text.empty() ? "" : ", ") + flaw;
  return text;
}

/// Builds one component's solid and checks it (BRepCheck, volume).
BuildReport buildOne(const Configuration& configuration, const graph::Component& component) {
  std::ostringstream line;
  line << "  " << std::left << std::setw(10) << component.nodeType << ' ' << std::setw(32) << component.uid << ' ';
  if (configuration.shapes().find(component.nodeType) == nullptr) return {line.str() + "no builder yet", true};
  const auto start = std::chrono::steady_clock::now();
  try {
    const TopoDS_Shape& solid = configuration.shapes().shapeOf(configuration, component.uid);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const BRepCheck_Analyzer analyzer(solid);
    const bool valid = analyzer.IsValid();
    line << (valid ? "valid solid" : "INVALID solid") << ", volume " << geometry::volumeOf(solid) << ", " << std::fixed
         << std::setprecision(3) << seconds << " s";
    if (!valid) line << " (BRepCheck: " << flawsOf(solid, analyzer) << ")";
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
