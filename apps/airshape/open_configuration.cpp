#include "open_configuration.h"

#include <algorithm>
#include <iostream>

#include "airshape/error.h"

namespace airshape::cli {

namespace {

/// The command-line flag of a build option: "duct_cutouts" -> "--duct-cutouts".
std::string flagOf(const std::string& option) {
  std::string flag = "--" + option;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

}  // namespace

std::vector<std::string> takeOptionFlags(std::vector<std::string>& arguments, const plugin::PluginHost& host) {
  std::vector<std::string> options;
  for (const ComponentCutOuts& cutOuts : host.shapes().cutOuts()) {
    const auto given = std::find(arguments.begin(), arguments.end(), flagOf(cutOuts.option));
    if (given == arguments.end()) continue;
    arguments.erase(std::remove(given, arguments.end(), flagOf(cutOuts.option)), arguments.end());
    options.push_back(cutOuts.option);
  }
  return options;
}

std::string optionFlagsHelp(const plugin::PluginHost& host) {
  std::string help;
  for (const ComponentCutOuts& cutOuts : host.shapes().cutOuts())
    help += flagOf(cutOuts.option) + "  " + cutOuts.description + "\n";
  return help;
}

Configuration openConfiguration(const std::string& path, const plugin::PluginHost& host) {
  return openConfiguration(CpacsInput{path, {}}, host);
}

Configuration openConfiguration(const CpacsInput& input, const plugin::PluginHost& host) {
  const std::string& path = input.path;
  Configuration configuration = Configuration::open(path, host.componentLocations());
  configuration.useShapes(host.shapes());
  for (const std::string& option : input.options) configuration.setOption(option, true);
  // A few lines say what was ignored; validate lists everything.
  constexpr std::size_t kShown = 5;
  Problems warnings = configuration.unreadableValues();
  for (Problem& unreadable : warnings) unreadable.message += " (left out of the model)";
  warnings.insert(warnings.end(), configuration.warnings().begin(), configuration.warnings().end());
  for (std::size_t i = 0; i < warnings.size() && i < kShown; ++i)
    std::cerr << path << ": warning: " << warnings[i].describe() << '\n';
  if (warnings.size() > kShown) {
    std::cerr << path << ": warning: " << warnings.size() - kShown << " more problems of this kind; `airshape validate "
              << path << "` lists them all\n";
  }
  return configuration;
}

void printGeometryWarnings(const Configuration& configuration) {
  for (const Problem& warning : configuration.geometryWarnings())
    std::cerr << configuration.source() << ": warning: " << warning.describe() << '\n';
}

std::string singleFileArgument(const std::vector<std::string>& arguments, const std::string& command) {
  for (const std::string& argument : arguments)
    if (argument.size() > 1 && argument[0] == '-')
      throw Error(ErrorCode::InvalidArgument,
                  command + ": unexpected argument '" + argument + "' (see airshape help " + command + ")");
  if (arguments.size() != 1 || arguments[0].empty() || arguments[0][0] == '-')
    throw Error(ErrorCode::InvalidArgument, "usage: airshape " + command + " FILE (see airshape help " + command + ")");
  return arguments[0];
}

}  // namespace airshape::cli
