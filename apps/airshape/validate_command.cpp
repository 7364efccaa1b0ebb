#include <iostream>

#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

int runValidate(const Arguments& arguments, plugin::PluginHost& host) {
  const std::string path = singleFileArgument(arguments, "validate");
  const Configuration configuration = Configuration::open(path, host.componentLocations());
  // The warnings of loading (uIDs, parents) are errors of the document too.
  Problems problems = configuration.schemaProblems();
  problems.insert(problems.end(), configuration.warnings().begin(), configuration.warnings().end());
  for (const Problem& problem : problems) std::cout << path << ": " << problem.describe() << '\n';
  std::cout << path << ": " << problems.size() << (problems.size() == 1 ? " problem" : " problems") << " (CPACS "
            << configuration.cpacsVersion() << ")\n";
  return problems.empty() ? kSuccess : kProblemsFound;
}

}  // namespace airshape::cli
