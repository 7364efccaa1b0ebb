#include <iostream>

#include "airshape/plugin/plugin_host.h"
#include "airshape/protected_output.h"
#include "airshape/query/query_service.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

int runQuery(const Arguments& arguments, plugin::PluginHost& host) {
  const std::string path = singleFileArgument(arguments, "query");
  Configuration configuration = openConfiguration(path, host);
  // Answers only on standard output: a library's stray print would break the protocol.
  ProtectedOutput output;
  query::serveQueries(configuration, host.queries(), std::cin, output.answers());
  printGeometryWarnings(configuration);
  return kSuccess;
}

}  // namespace airshape::cli
