#pragma once

#include <string>

#include "airshape/configuration.h"
#include "airshape/plugin/plugin_host.h"

namespace airshape::cli {

/// Opens a CPACS file with the component types the loaded plugins know, and prints what
/// loading ignored or worked around (duplicate uIDs, dangling uIDrefs) on stderr.
Configuration openConfiguration(const std::string& path, const plugin::PluginHost& host);

/// Prints on stderr what building found odd but built all the same (a profile crossing itself
/// within the tolerance), one line each: `FILE: warning: XPATH: message`.
void printGeometryWarnings(const Configuration& configuration);

/// The single file argument of a command; throws a usage Error otherwise.
std::string singleFileArgument(const std::vector<std::string>& arguments, const std::string& command);

}  // namespace airshape::cli
