#include <iostream>

#include "airshape/plugin/plugin_host.h"
#include "airshape/query/query_service.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

int runQuery(const Arguments& arguments, plugin::PluginHost& host) {
  const std::string path = singleFileArgument(arguments, "query");
  Configuration configuration = openConfiguration(path, host);
  query::serveQueries(configuration, host.queries(), std::cin, std::cout);
  printGeometryWarnings(configuration);
  return kSuccess;
}

}  // namespace airshape::cli
