#include <iostream>

#include "airshape/plugin/plugin_host.h"
#include "airshape/protected_output.h"
#include "airshape/query/query_service.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

int runQuery(const Arguments& given, plugin::PluginHost& host) {
  Arguments arguments = given;
  const std::vector<std::string> options = takeOptionFlags(arguments, host);
  const std::string path = singleFileArgument(arguments, "query");
  Configuration configuration = openConfiguration({path, options}, host);
  // Answers only on standard output: a library's stray print would break the protocol.
  ProtectedOutput output;
  query::serveQueries(configuration, host.queries(), std::cin, output.answers());
  printGeometryWarnings(configuration);
  return kSuccess;
}

}  // namespace airshape::cli
