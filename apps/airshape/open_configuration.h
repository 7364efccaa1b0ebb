#pragma once

#include <string>
#include <vector>

#include "airshape/configuration.h"
#include "airshape/plugin/plugin_host.h"

namespace airshape::cli {

/// A CPACS file a command opens, and the build options its flags turn on in it.
struct CpacsInput {
  std::string path;
  std::vector<std::string> options;  ///< e.g. "duct_cutouts" for --duct-cutouts
};

/// Opens a CPACS file with the component types the loaded plugins know, turns on the build
/// options asked for, and prints what loading ignored or worked around (duplicate uIDs,
/// dangling uIDrefs) on stderr.
Configuration openConfiguration(const CpacsInput& input, const plugin::PluginHost& host);
Configuration openConfiguration(const std::string& path, const plugin::PluginHost& host);

/// Takes the flags that turn the loaded plugins' build options on out of a command's arguments
/// (`--duct-cutouts` for the option "duct_cutouts"): the options, in the order given. The rest of
/// the arguments stay for the command.
std::vector<std::string> takeOptionFlags(std::vector<std::string>& arguments, const plugin::PluginHost& host);

/// The help text of those flags, one line each ("" when no plugin declares an option).
std::string optionFlagsHelp(const plugin::PluginHost& host);

/// Prints on stderr what building found odd but built all the same (a profile crossing itself
/// within the tolerance), one line each: `FILE: warning: XPATH: message`.
void printGeometryWarnings(const Configuration& configuration);

/// The single file argument of a command; throws a usage Error otherwise.
std::string singleFileArgument(const std::vector<std::string>& arguments, const std::string& command);

}  // namespace airshape::cli
