#pragma once

#include <string>
#include <vector>

namespace airshape::plugin {
class PluginHost;
}

namespace airshape::cli {

/// Exit statuses of the airshape command.
enum ExitStatus { kSuccess = 0, kProblemsFound = 1, kFailure = 2 };

using Arguments = std::vector<std::string>;

// One function per command; each returns the exit status and lets Error propagate to main,
// which prints it as one line on stderr.
int runInfo(const Arguments& arguments, plugin::PluginHost& host);
int runQuery(const Arguments& arguments, plugin::PluginHost& host);
int runValidate(const Arguments& arguments, plugin::PluginHost& host);
int runSave(const Arguments& arguments, plugin::PluginHost& host);
int runPlugins(const Arguments& arguments, plugin::PluginHost& host);
int runGordon(const Arguments& arguments, plugin::PluginHost& host);
int runBuild(const Arguments& arguments, plugin::PluginHost& host);
int runExport(const Arguments& arguments, plugin::PluginHost& host);
int runView(const Arguments& arguments, plugin::PluginHost& host);
int runMesh(const Arguments& arguments, plugin::PluginHost& host);
/// Runs the Python package's study engine (study_command.cpp).
int runStudy(const Arguments& arguments, plugin::PluginHost& host);
/// Load the module of `export` and `view`, or of `mesh`, and run the command there
/// (command_modules.cpp).
int runExportModule(const Arguments& arguments, plugin::PluginHost& host);
int runViewModule(const Arguments& arguments, plugin::PluginHost& host);
int runMeshModule(const Arguments& arguments, plugin::PluginHost& host);

}  // namespace airshape::cli
