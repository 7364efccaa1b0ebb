// The control-surface plugin: leading- and trailing-edge devices and spoilers of wing
// component segments. It answers the device ops that need no geometry (count, uIDs, kinds,
// control parameter ranges); it builds no device geometry yet.
#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/primary_model.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/query/arguments.h"
#include "airshape/query/model_selection.h"
#include "device_list.h"

namespace airshape::controlsurfaces {
namespace {

using query::Json;

const schema::WingType& selectWing(const Configuration& configuration, const Json& query) {
  return query::selectInFirstModel(configuration, model::primaryModel(configuration).wings, query, "wing", "wing");
}

/// The uID of the device a query's 1-based `index` names among `devices`.
std::string nthUid(const std::vector<Device>& devices, const Json& query, const std::string& kind) {
  std::vector<std::string> uids;
  for (const Device& device : devices) uids.push_back(device.uid);
  if (!query.contains("index") || !query.at("index").is_number_integer())
    throw Error(ErrorCode::InvalidArgument, "argument 'index' must be a 1-based integer");
  return uids[query::selectByIndexOrUid(query, "index", uids, kind)];
}

/// The control parameters of a device's first and last step (QUERY-components §3.3).
Json parameterRange(const Device& device) {
  if (device.path == nullptr || !device.path->steps || device.path->steps->step.empty())
    throw Error(ErrorCode::InvalidModel, "the control surface has no path steps", {}, device.xpath + "/path");
  const auto& steps = device.path->steps->step;
  return {{"min", steps[0].controlParameter}, {"max", steps[steps.size() - 1].controlParameter}};
}

class ControlSurfacesPlugin final : public plugin::BasicPlugin {
 public:
  ControlSurfacesPlugin()
      : BasicPlugin("controlsurfaces", "0.1.0", "flaps, slats, ailerons and spoilers of wings (no geometry yet)",
                    {{"trailingEdgeDevice", ""}, {"leadingEdgeDevice", ""}, {"spoiler", ""}},
                    {{"wing", "0.1.0", "1.0.0"}}) {}

  void registerQueries(query::QueryRegistry& registry) const override {
    registry.add({"control_surface_count", "", "wing -> number of trailing- and leading-edge devices (no spoilers)",
                  [](Configuration& c, const Json& q) -> Json { return countedDevicesOf(selectWing(c, q)).size(); }});
    registry.add({"control_surface_uid", "", "wing, index -> uID of the wing's index-th device",
                  [](Configuration& c, const Json& q) -> Json {
                    return nthUid(countedDevicesOf(selectWing(c, q)), q, "control surface");
                  }});
    registry.add({"spoiler_count", "", "wing -> number of spoilers",
                  [](Configuration& c, const Json& q) -> Json { return spoilersOf(selectWing(c, q)).size(); }});
    registry.add(
        {"spoiler_uid", "", "wing, index -> uID of the wing's index-th spoiler",
         [](Configuration& c, const Json& q) -> Json { return nthUid(spoilersOf(selectWing(c, q)), q, "spoiler"); }});
    registry.add({"control_surface_type", "", "uid -> trailing_edge_device, leading_edge_device or spoiler",
                  [](Configuration& c, const Json& q) -> Json {
                    return kindName(deviceNamed(c, query::stringArgument(q, "uid")).kind);
                  }});
    registry.add({"control_surface_parameter_range", "",
                  "uid -> {min, max}: control parameters of its first and last step",
                  [](Configuration& c, const Json& q) -> Json {
                    return parameterRange(deviceNamed(c, query::stringArgument(q, "uid")));
                  }});
  }
};

}  // namespace
}  // namespace airshape::controlsurfaces

AIRSHAPE_PLUGIN(airshape::controlsurfaces::ControlSurfacesPlugin)
