#include <cctype>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <optional>
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

/// How a component is named on its line: its uID, or its path when it has none.
std::string nameOf(const graph::Component& component) {
  return component.uid.empty() ? component.xpath : component.uid;
}

/// Builds one component's shape and checks it (BRepCheck; volume of a solid, area of faces);
/// a component no plugin builds says why.
BuildReport buildOne(const Configuration& configuration, const plugin::PluginHost& host,
                     const graph::Component& component) {
  std::ostringstream line;
  line << "  " << std::left << std::setw(18) << component.typeName << ' ' << std::setw(32) << nameOf(component) << ' ';
  if (configuration.shapes().find(component.nodeType) == nullptr) {
    const std::string plugin = host.pluginFor(component.nodeType);
    if (plugin.empty()) return {line.str() + "not supported: no loaded plugin builds " + component.nodeType, true};
    if (const std::string* why = configuration.shapes().declined(component.nodeType))
      return {line.str() + "not built: " + *why + " (plugin " + plugin + ")", true};
    return {line.str() + "no builder yet for " + component.typeName + " (plugin " + plugin + ")", true};
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    const TopoDS_Shape& solid = configuration.shapes().shapeOf(configuration, component.uid);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // A plugin that returns nothing has failed, whatever BRepCheck says of an empty shape.
    if (solid.IsNull() || !TopExp_Explorer(solid, TopAbs_VERTEX).More())
      return {line.str() + "FAILED: the plugin built an empty shape", false};
    const BRepCheck_Analyzer analyzer(solid);
    const bool valid = analyzer.IsValid();
    // Structure is surfaces (spar webs, ribs: measured by their area, not a volume) or lines
    // (frames, stringers, beams: by their length).
    if (TopExp_Explorer(solid, TopAbs_SOLID).More())
      line << (valid ? "valid solid" : "INVALID solid") << ", volume " << geometry::enclosedVolume(solid);
    else if (TopExp_Explorer(solid, TopAbs_FACE).More())
      line << (valid ? "valid faces" : "INVALID faces") << ", area " << geometry::areaOf(solid);
    else
      line << (valid ? "valid lines" : "INVALID lines") << ", length " << geometry::lengthOf(solid);
    line << ", " << std::fixed << std::setprecision(3) << seconds << " s";
    if (!valid) line << " (BRepCheck: " << flawsOf(solid, analyzer) << ")";
    return {line.str(), valid};
  } catch (const Error& error) {
    line << "FAILED: " << error.what();
  } catch (const Standard_Failure& failure) {
    line << "FAILED: geometry kernel failure: " << failure.GetMessageString();
  }
  return {line.str(), false};
}

/// The components `build` builds, in build order: all but the parts of others' solids.
std::vector<std::size_t> builtOnTheirOwn(const graph::ComponentGraph& graph) {
  std::vector<std::size_t> order;
  for (std::size_t index : graph.buildOrder())
    if (!graph.components()[index].part) order.push_back(index);
  return order;
}

/// Builds every component, independent ones in parallel.
std::vector<BuildReport> buildAll(const Configuration& configuration, const plugin::PluginHost& host) {
  const graph::ComponentGraph& graph = configuration.components();
  std::vector<BuildReport> reports(graph.components().size());
  graph::forEachByDepth(graph, builtOnTheirOwn(graph), [&](std::size_t index) {
    reports[index] = buildOne(configuration, host, graph.components()[index]);
  });
  return reports;
}

/// Why nothing is built, if nothing is: the file holds no component, or no loaded plugin
/// builds any of its components.
std::optional<std::string> nothingToBuild(const Configuration& configuration) {
  const std::vector<std::size_t> order = builtOnTheirOwn(configuration.components());
  if (order.empty()) return "the file holds no geometric component";
  for (std::size_t index : order)
    if (configuration.shapes().find(configuration.components().components()[index].nodeType) != nullptr)
      return std::nullopt;
  return "no loaded plugin builds any of its " + std::to_string(order.size()) + " components";
}

}  // namespace

int runBuild(const Arguments& given, plugin::PluginHost& host) {
  Arguments arguments = given;
  const std::vector<std::string> options = takeOptionFlags(arguments, host);
  const std::string path = singleFileArgument(arguments, "build");
  const Configuration configuration = openConfiguration({path, options}, host);
  const graph::ComponentGraph& graph = configuration.components();
  const std::vector<std::size_t> order = builtOnTheirOwn(graph);
  std::cout << path << ": building " << order.size() << " components\n";
  const std::vector<BuildReport> reports = buildAll(configuration, host);
  bool allGood = true;
  for (std::size_t index : order) {
    std::cout << reports[index].line << '\n';
    allGood = reports[index].good && allGood;
  }
  if (const std::optional<std::string> why = nothingToBuild(configuration))
    std::cout << path << ": nothing to build: " << *why << '\n';
  printGeometryWarnings(configuration);
  return allGood ? kSuccess : kProblemsFound;
}

}  // namespace airshape::cli
