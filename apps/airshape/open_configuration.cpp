#include "open_configuration.h"

#include <iostream>

#include "airshape/error.h"

namespace airshape::cli {

Configuration openConfiguration(const std::string& path, const plugin::PluginHost& host) {
  Configuration configuration = Configuration::open(path, host.componentLocations());
  configuration.useShapes(host.shapes());
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
  if (arguments.size() != 1 || arguments[0].empty() || arguments[0][0] == '-')
    throw Error(ErrorCode::InvalidArgument, "usage: airshape " + command + " FILE (see airshape help " + command + ")");
  return arguments[0];
}

}  // namespace airshape::cli
