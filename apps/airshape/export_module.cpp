// `airshape export` and `airshape view` run in a module of their own
// (libairshape_export_command.so, next to the core library), loaded only for those commands:
// it links OCCT's data-exchange toolkits, which Debian builds with BIND_NOW, and loading them
// costs every process about 80 ms.
#include <boost/dll/shared_library.hpp>

#include "airshape/error.h"
#include "airshape/plugin/plugin_host.h"
#include "commands.h"

namespace airshape::cli {

namespace {

using CommandEntry = int(const Arguments&, plugin::PluginHost&);

/// A command's entry in the module, which is loaded once and never unloaded (errors thrown
/// in it are caught after it returns).
CommandEntry& entryInModule(const char* symbol) {
  static const boost::dll::shared_library module = [] {
    const boost::dll::fs::path path =
        boost::dll::fs::path(plugin::PluginHost::coreLibraryFolder()) / "libairshape_export_command.so";
    boost::dll::fs::error_code error;
    boost::dll::shared_library loaded(path, boost::dll::load_mode::default_mode, error);
    if (error) throw Error(ErrorCode::PluginFailed, "cannot load the export module: " + error.message(), path.string());
    return loaded;
  }();
  return module.get<CommandEntry>(symbol);
}

}  // namespace

int runExportModule(const Arguments& arguments, plugin::PluginHost& host) {
  return entryInModule("airshape_run_export")(arguments, host);
}

int runViewModule(const Arguments& arguments, plugin::PluginHost& host) {
  return entryInModule("airshape_run_view")(arguments, host);
}

}  // namespace airshape::cli
