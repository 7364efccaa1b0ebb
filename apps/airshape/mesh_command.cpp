// `airshape mesh`: meshes for CFD and FEM through Gmsh (docs/meshing.md), in a module of its
// own (libairshape_mesh_command.so) that only this command loads: it links Gmsh.
#include <filesystem>
#include <iomanip>
#include <iostream>

#include <boost/config.hpp>

#include "airshape/error.h"
#include "airshape/meshing/mesher.h"
#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"
#include "output_paths.h"

namespace airshape::cli {

namespace {

struct MeshCommandOptions {
  std::string input;
  std::vector<std::string> outputs;
  meshing::MeshOptions meshOptions;
  bool force = false;
  bool quiet = false;
};

MeshCommandOptions parseMeshOptions(Arguments arguments) {
  MeshCommandOptions options;
  options.meshOptions = meshing::takeMeshOptions(arguments);
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if ((argument == "-o" || argument == "--output") && i + 1 < arguments.size()) {
      options.outputs.push_back(arguments[++i]);
    } else if (argument == "--force") {
      options.force = true;
    } else if (argument == "--quiet" || argument == "-q") {
      options.quiet = true;
    } else if (!argument.empty() && argument[0] != '-' && options.input.empty()) {
      options.input = argument;
    } else {
      throw Error(ErrorCode::InvalidArgument, "mesh: unexpected argument '" + argument + "' (see airshape help mesh)");
    }
  }
  if (options.input.empty() || options.outputs.empty())
    throw Error(ErrorCode::InvalidArgument, "usage: airshape mesh FILE -o OUT [-o OUT ...] [options]");
  return options;
}

/// Refuses, before anything is built, outputs of unknown formats, in missing folders, and
/// existing files (unless --force).
void checkOutputs(const MeshCommandOptions& options) {
  for (const std::string& output : options.outputs) meshing::meshFormatOfPath(output);
  refuseUnwritableOutputs(options.outputs, options.force);
}

/// Progress on stderr once meshing has taken a second: quick meshes stay quiet.
void printProgress(const meshing::MeshProgress& progress) {
  if (progress.seconds < 1.0) return;
  std::cerr << "mesh: " << progress.step << ", " << std::fixed << std::setprecision(1) << progress.seconds << " s\n";
}

}  // namespace

int runMesh(const Arguments& given, plugin::PluginHost& host) {
  Arguments arguments = given;
  const std::vector<std::string> buildOptions = takeOptionFlags(arguments, host);
  MeshCommandOptions options = parseMeshOptions(arguments);
  checkOutputs(options);
  const Configuration configuration = openConfiguration({options.input, buildOptions}, host);
  if (!options.quiet) options.meshOptions.progress = printProgress;
  const meshing::MeshReport report = meshing::meshConfiguration(configuration, options.outputs, options.meshOptions);
  for (const std::string& failure : report.failures) std::cerr << "mesh: failed: " << failure << '\n';
  for (const std::string& note : report.notes) std::cerr << "mesh: note: " << note << '\n';
  printGeometryWarnings(configuration);
  if (!options.quiet) {
    for (const std::string& output : options.outputs)
      std::cerr << "mesh: wrote " << output << " (" << meshing::meshFormatName(meshing::meshFormatOfPath(output))
                << ", " << std::filesystem::file_size(output) / 1024 << " KiB)\n";
  }
  for (const meshing::MeshSummary& summary : report.meshes) std::cout << meshing::summaryLine(summary) << '\n';
  return report.failures.empty() ? kSuccess : kProblemsFound;
}

}  // namespace airshape::cli

// The entry the airshape command looks up when it loads this module (command_modules.cpp).
extern "C" BOOST_SYMBOL_EXPORT int airshape_run_mesh(const airshape::cli::Arguments& arguments,
                                                     airshape::plugin::PluginHost& host) {
  return airshape::cli::runMesh(arguments, host);
}
