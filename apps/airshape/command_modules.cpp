// Commands that link large libraries run in modules of their own, next to the core library,
// loaded only for those commands: `export` and `view` (libairshape_export_command.so) link
// OCCT's data-exchange toolkits, which Debian builds with BIND_NOW and which cost every process
// about 80 ms to load; `mesh` (libairshape_mesh_command.so) links Gmsh, and is there only in
// builds with meshing.
#include <map>

#include <boost/dll/shared_library.hpp>

#include "airshape/error.h"
#include "airshape/plugin/plugin_host.h"
#include "commands.h"

namespace airshape::cli {

namespace {

using CommandEntry = int(const Arguments&, plugin::PluginHost&);

/// A command's entry in a module, which is loaded once and never unloaded (errors thrown in it
/// are caught after it returns). `missing` says why a build may lack the module.
CommandEntry& entryInModule(const std::string& file, const char* symbol, const std::string& missing) {
  static std::map<std::string, boost::dll::shared_library> modules;
  auto loaded = modules.find(file);
  if (loaded == modules.end()) {
    const boost::dll::fs::path path = boost::dll::fs::path(plugin::PluginHost::coreLibraryFolder()) / file;
    boost::dll::fs::error_code exists;
    if (!boost::dll::fs::exists(path, exists) && !missing.empty())
      throw Error(ErrorCode::NotImplemented, missing, path.string());
    boost::dll::fs::error_code error;
    boost::dll::shared_library module(path, boost::dll::load_mode::default_mode, error);
    if (error)
      throw Error(ErrorCode::PluginFailed, "cannot load the module " + file + ": " + error.message(), path.string());
    loaded = modules.emplace(file, std::move(module)).first;
  }
  return loaded->second.get<CommandEntry>(symbol);
}

}  // namespace

int runExportModule(const Arguments& arguments, plugin::PluginHost& host) {
  return entryInModule("libairshape_export_command.so", "airshape_run_export", "")(arguments, host);
}

int runViewModule(const Arguments& arguments, plugin::PluginHost& host) {
  return entryInModule("libairshape_export_command.so", "airshape_run_view", "")(arguments, host);
}

int runMeshModule(const Arguments& arguments, plugin::PluginHost& host) {
  return entryInModule("libairshape_mesh_command.so", "airshape_run_mesh",
                       "this build has no meshing: install Gmsh's development files (apt install libgmsh-dev) "
                       "and build again (docs/meshing.md)")(arguments, host);
}

}  // namespace airshape::cli
