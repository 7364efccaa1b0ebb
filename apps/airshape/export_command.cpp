#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <utility>
#include <vector>

#include <boost/config.hpp>

#include "airshape/error.h"
#include "airshape/export/exporter.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/parallel_for.h"
#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"
#include "output_paths.h"

namespace airshape::cli {

namespace {

using Clock = std::chrono::steady_clock;

struct ExportCommandOptions {
  std::string input;
  std::vector<std::string> outputs;
  exporting::ExportOptions exportOptions;
  bool force = false;
  bool quiet = false;
};

/// --deflection LINEAR[,ANGULAR]: metres, and radians for the angle.
void parseDeflection(const std::string& text, exporting::ExportOptions& options) {
  const std::vector<std::string> parts = exporting::splitAtCommas(text);
  if (parts.empty() || parts.size() > 2)
    throw Error(ErrorCode::InvalidArgument, "--deflection: expected LINEAR or LINEAR,ANGULAR, got '" + text + "'");
  options.linearDeflection = exporting::positiveNumber(parts[0], "--deflection");
  if (parts.size() == 2) options.angularDeflection = exporting::positiveNumber(parts[1], "--deflection");
}

ExportCommandOptions parseExportOptions(const Arguments& arguments) {
  ExportCommandOptions options;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    const bool hasValue = i + 1 < arguments.size();
    if ((argument == "-o" || argument == "--output") && hasValue) {
      options.outputs.push_back(arguments[++i]);
    } else if (argument == "--components" && hasValue) {
      options.exportOptions.components = exporting::splitAtCommas(arguments[++i]);
    } else if (argument == "--deflection" && hasValue) {
      parseDeflection(arguments[++i], options.exportOptions);
    } else if (argument == "--deflect" && hasValue) {
      const std::vector<exporting::Pose> poses = exporting::parsePoses(arguments[++i]);
      options.exportOptions.poses.insert(options.exportOptions.poses.end(), poses.begin(), poses.end());
    } else if (argument == "--structure") {
      options.exportOptions.structure = true;
    } else if (argument == "--profiles") {
      options.exportOptions.profiles = true;
    } else if (argument == "--mirror") {
      options.exportOptions.mirror = true;
    } else if (argument == "--fused") {
      options.exportOptions.fused = true;
    } else if (argument == "--force") {
      options.force = true;
    } else if (argument == "--quiet" || argument == "-q") {
      options.quiet = true;
    } else if (!argument.empty() && argument[0] != '-' && options.input.empty()) {
      options.input = argument;
    } else {
      throw Error(ErrorCode::InvalidArgument,
                  "export: unexpected argument '" + argument + "' (see airshape help export)");
    }
  }
  if (options.input.empty() || options.outputs.empty())
    throw Error(ErrorCode::InvalidArgument, "usage: airshape export FILE -o OUT [-o OUT ...] [options]");
  return options;
}

/// Refuses, before anything is built, outputs of unknown formats, in missing folders, and
/// existing files (unless --force).
void checkOutputs(const ExportCommandOptions& options) {
  for (const std::string& output : options.outputs) exporting::formatOfPath(output);
  refuseUnwritableOutputs(options.outputs, options.force);
}

void printProgress(const exporting::ExportProgress& progress) {
  std::cerr << "export: ";
  if (progress.componentsTotal > 0) std::cerr << progress.componentsBuilt << '/' << progress.componentsTotal << ' ';
  std::cerr << progress.step << ", " << std::fixed << std::setprecision(2) << progress.seconds << " s\n";
}

/// The one-screen summary: each solid written with its volume and area. The solids are
/// measured on every core: a wing with its cut-outs has trimmed faces, which take OCCT's
/// adaptive integration (CPACS_30_aircraft_flaps.xml with every device deflected: 0.43 s of
/// its 1.7 s export on one core, 0.21-0.25 s on two).
void printSummary(const exporting::ExportScene& scene) {
  std::vector<std::pair<double, double>> measures(scene.components.size());
  parallelFor(scene.components.size(), [&](std::size_t index) {
    const TopoDS_Shape& shape = scene.components[index].shape.shape;
    measures[index] = {geometry::enclosedVolume(shape), geometry::areaOf(shape)};
  });
  std::cout << std::left << std::setw(36) << "component" << std::right << std::setw(14) << "volume [m3]"
            << std::setw(14) << "area [m2]" << '\n';
  for (std::size_t index = 0; index < scene.components.size(); ++index)
    std::cout << std::left << std::setw(36) << scene.components[index].name << std::right << std::fixed
              << std::setprecision(4) << std::setw(14) << measures[index].first << std::setw(14)
              << measures[index].second << '\n';
}

/// "a, b, c"
std::string joined(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

/// How many geometric elements of the file no loaded plugin builds yet.
std::size_t withoutBuilder(const Configuration& configuration) {
  std::size_t count = 0;
  for (const graph::Component& component : configuration.components().components())
    count += component.nodeType != graph::kModelNodeType && configuration.shapes().find(component.nodeType) == nullptr;
  return count;
}

/// Whether a component named with --components is among those left out (the structure,
/// devices or segments it brings with it may fail on their own: they are said, not fatal).
bool namedComponentFailed(const exporting::ExportScene& scene, const ExportCommandOptions& options) {
  for (const std::string& leftOut : scene.leftOut)
    for (const std::string& uid : options.exportOptions.components)
      if (leftOut.compare(0, uid.size() + 1, uid + ":") == 0) return true;
  return false;
}

/// Why nothing is written, if nothing is: no plugin builds any component (or, for the
/// structural model, no component holds structure), every component failed, or a component
/// named with --components failed (an export of what was asked for).
std::optional<std::string> nothingToWrite(const exporting::ExportScene& scene, const ExportCommandOptions& options) {
  if (scene.components.empty() && options.exportOptions.structure)
    return "no component of " + options.input +
           (options.exportOptions.components.empty() ? "" : " named with --components") +
           " holds spars or ribs that could be built";
  if (scene.components.empty() && scene.leftOut.empty())
    return "nothing to build: no loaded plugin builds any component of " + options.input +
           (options.exportOptions.components.empty() ? "" : " named with --components");
  if (scene.components.empty()) return "no component could be built";
  if (namedComponentFailed(scene, options)) return "a component named with --components could not be built";
  return std::nullopt;
}

}  // namespace

int runExport(const Arguments& given, plugin::PluginHost& host) {
  Arguments arguments = given;
  const std::vector<std::string> buildOptions = takeOptionFlags(arguments, host);
  ExportCommandOptions options = parseExportOptions(arguments);
  checkOutputs(options);
  const Clock::time_point start = Clock::now();
  const Configuration configuration = openConfiguration({options.input, buildOptions}, host);
  if (!options.quiet) options.exportOptions.progress = printProgress;
  options.exportOptions.skipFailed = true;  // each failure is said; the exit status tells
  const exporting::ExportScene scene = exporting::buildScene(configuration, options.exportOptions);
  for (const std::string& leftOut : scene.leftOut) std::cerr << "export: left out " << leftOut << '\n';
  for (const std::string& note : scene.notes) std::cerr << "export: note: " << note << '\n';
  if (const std::size_t unbuilt = withoutBuilder(configuration); unbuilt > 0 && !options.quiet)
    std::cerr << "export: " << unbuilt << " geometric elements are not built and not written (`airshape build "
              << options.input << "` says why for each)\n";
  printGeometryWarnings(configuration);
  if (const std::optional<std::string> why = nothingToWrite(scene, options)) {
    std::cerr << "export: " << *why << "; no file written\n";
    return scene.leftOut.empty() ? kSuccess : kProblemsFound;
  }
  for (const std::string& output : options.outputs) {
    const exporting::Format format = exporting::formatOfPath(output);
    const Clock::time_point writing = Clock::now();
    if (const std::vector<std::string> lines = exporting::componentsLeftOutOf(scene, format);
        !lines.empty() && lines.size() < scene.components.size())
      std::cerr << "export: note: " << output << " leaves out " << joined(lines) << ": lines, which "
                << exporting::formatName(format)
                << " cannot hold (.vtp, .glb, .gltf, .obj, .step, .iges and .brep can)\n";
    exporting::writeScene(scene, output, format, options.exportOptions);
    if (!options.quiet)
      std::cerr << "export: wrote " << output << " (" << exporting::formatName(format) << ", "
                << std::filesystem::file_size(output) / 1024 << " KiB, " << std::fixed << std::setprecision(2)
                << std::chrono::duration<double>(Clock::now() - writing).count() << " s)\n";
  }
  if (!options.quiet) {
    printSummary(scene);
    std::cout << "total time " << std::fixed << std::setprecision(2)
              << std::chrono::duration<double>(Clock::now() - start).count() << " s\n";
  }
  return scene.leftOut.empty() ? kSuccess : kProblemsFound;
}

}  // namespace airshape::cli

// The entry the airshape command looks up when it loads this module (command_modules.cpp).
extern "C" BOOST_SYMBOL_EXPORT int airshape_run_export(const airshape::cli::Arguments& arguments,
                                                       airshape::plugin::PluginHost& host) {
  return airshape::cli::runExport(arguments, host);
}
