// Fuzz target: one line of the query service against the project's example aircraft, loaded
// once with every plugin, as `airshape query` answers it. Every line gets an answer; nothing
// may crash or hang. Queries are stateless, so one configuration serves every input.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "airshape/configuration.h"
#include "airshape/plugin/plugin_host.h"
#include "airshape/query/query_service.h"

namespace {

airshape::Configuration& exampleAircraft() {
  static const std::unique_ptr<airshape::Configuration> configuration = [] {
    const airshape::plugin::PluginHost& host = airshape::plugin::processPlugins();
    auto loaded = std::make_unique<airshape::Configuration>(airshape::Configuration::open(
        std::string(AIRSHAPE_SOURCE_DIR) + "/examples/example-aircraft.xml", host.componentLocations()));
    loaded->useShapes(host.shapes());
    return loaded;
  }();
  return *configuration;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string line(reinterpret_cast<const char*>(data), size);
  (void)airshape::query::answer(exampleAircraft(), airshape::plugin::processPlugins().queries(), line);
  return 0;
}
