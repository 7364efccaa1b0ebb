#include <iostream>

#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

int runValidate(const Arguments& arguments, plugin::PluginHost& host) {
  const std::string path = singleFileArgument(arguments, "validate");
  const Configuration configuration = Configuration::open(path, host.componentLocations());
  Problems problems = configuration.schemaProblems();
  for (const Problem& problem : configuration.uids().problems()) problems.push_back(problem);
  for (const Problem& warning : configuration.warnings())
    if (warning.message.find("parentUID") != std::string::npos) problems.push_back(warning);
  for (const Problem& problem : problems) std::cout << path << ": " << problem.describe() << '\n';
  std::cout << path << ": " << problems.size() << (problems.size() == 1 ? " problem" : " problems") << " (CPACS "
            << configuration.cpacsVersion() << ")\n";
  return problems.empty() ? kSuccess : kProblemsFound;
}

}  // namespace airshape::cli
