// The control-surface plugin: leading- and trailing-edge devices and spoilers of wing
// component segments. It builds each device from its wing, through the wing plugin's public
// interface (airshape/wing/wing_services.h), and answers the device ops of the query
// protocol (QUERY-components §3).
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/query/arguments.h"
#include "airshape/query/box_answer.h"
#include "airshape/query/model_selection.h"
#include "airshape/wing/wing_list.h"
#include "device_geometry.h"
#include "device_list.h"
#include "device_services.h"
#include "hinge_motion.h"

namespace airshape::controlsurfaces {
namespace {

using query::Json;
using Services = std::shared_ptr<const wing::WingServices>;

const schema::WingType& selectWing(const Configuration& configuration, const Json& query) {
  return query::selectInFirstModel(configuration, wing::wingsOf(configuration), wing::wingNodeTypes(), query, "wing",
                                   "wing");
}

/// The uID of the device a query's 1-based `index` names among `devices`.
std::string nthUid(const std::vector<Device>& devices, const Json& query, const std::string& kind) {
  std::vector<std::string> uids;
  for (const Device& device : devices) uids.push_back(device.uid);
  if (!query.contains("index") || !query.at("index").is_number_integer())
    throw Error(ErrorCode::InvalidArgument, "argument 'index' must be a 1-based integer");
  return uids[query::selectByIndexOrUid(query, "index", uids, kind)];
}

/// The control parameter a device holds when asked for `p`: the reference ignores changes of
/// at most 1e-6 from the device's initial value (0, clamped to the range).
double heldParameter(const DeviceGeometry& device, double p) {
  const auto [first, last] = device.parameterRange();
  const double initial = std::clamp(0.0, std::min(first, last), std::max(first, last));
  return std::abs(p - initial) <= 1e-6 ? initial : p;
}

Json motionJson(double p, const gp_Trsf& motion) {
  Json rows = Json::array();
  for (int row = 1; row <= 3; ++row)
    rows.push_back({motion.Value(row, 1), motion.Value(row, 2), motion.Value(row, 3), motion.Value(row, 4)});
  return {{"control_parameter", p}, {"rotation", rotationAngle(motion)}, {"matrix", rows}};
}

/// The devices of a wing's component segments: inside the wing's solid, cut from it. The
/// reference library has no component for spoilers: they are built but not listed.
std::vector<plugin::NodeType> declaredNodeTypes() {
  std::vector<plugin::NodeType> types;
  for (const auto& [device, folder] : {std::pair<const char*, const char*>{"trailingEdgeDevice", "trailingEdgeDevices"},
                                       {"leadingEdgeDevice", "leadingEdgeDevices"},
                                       {"spoiler", "spoilers"}})
    types.push_back(plugin::NodeType{device, std::string("controlSurfaces/") + folder + "/" + device}
                        .inside("wingComponentSegment")
                        .typed("control_surface")
                        .asInsideParent());
  types.back() = types.back().unlisted();
  return types;
}

class ControlSurfacesPlugin final : public plugin::BasicPlugin {
 public:
  ControlSurfacesPlugin()
      : BasicPlugin("controlsurfaces", "0.3.0", "flaps, slats, ailerons and spoilers of wings", declaredNodeTypes(),
                    {{"wing", "0.1.0", "1.0.0"}}) {}

  void useServices(const plugin::ServiceRegistry& services) override {
    wing_ = services.find<wing::WingServices>(wing::kWingServices);
  }

  void offerServices(plugin::ServiceRegistry& services) const override {
    services.offer<DeviceServices>(kDeviceServices, makeDeviceServices(wing_));
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    const Services wing = wing_;
    const ShapeBuilder atRest = [wing](const Configuration& c, const std::string& uid) {
      return DeviceGeometry(c, *wing, deviceInAnyModel(c, uid)).atRest();
    };
    ComponentMotion motion;
    motion.range = [](const Configuration& c, const std::string& uid) {
      return parameterRangeOf(deviceInAnyModel(c, uid));
    };
    motion.at = [wing](const Configuration& c, const std::string& uid, double p) {
      const DeviceGeometry device(c, *wing, deviceInAnyModel(c, uid));
      return device.motionAt(heldParameter(device, p));
    };
    // The wing loses the whole ruled solid between the borders (the device and its cove) and
    // the skins its wingCutOut names.
    motion.cutOut = [wing](const Configuration& c, const std::string& uid) {
      const DeviceGeometry device(c, *wing, deviceInAnyModel(c, uid));
      NamedShape cutOut = device.cutter();
      if (const TopoDS_Shape skins = device.skinCutOut(); !skins.IsNull()) {
        TopoDS_Compound both;
        BRep_Builder builder;
        builder.MakeCompound(both);
        builder.Add(both, cutOut.shape);
        builder.Add(both, skins);
        for (TopExp_Explorer face(skins, TopAbs_FACE); face.More(); face.Next())
          cutOut.faces.emplace_back("", TopoDS::Face(face.Current()));
        cutOut.shape = both;
      }
      for (auto& face : cutOut.faces) face.first = uid + "/cut-out";
      return cutOut;
    };
    for (const char* type : {"trailingEdgeDevice", "leadingEdgeDevice", "spoiler"}) {
      shapes.add(type, atRest);
      shapes.addMotion(type, motion);
    }
  }

  void registerQueries(query::QueryRegistry& registry) const override {
    registerListing(registry);
    registerMotion(registry);
  }

 private:
  /// The ops that need no geometry: counts, uIDs, kinds, ranges.
  static void registerListing(query::QueryRegistry& registry) {
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
                    const auto [first, last] = parameterRangeOf(deviceNamed(c, query::stringArgument(q, "uid")));
                    return Json{{"min", first}, {"max", last}};
                  }});
  }

  /// The ops of a deflected device: its rigid motion and the measures of its moved shape.
  void registerMotion(query::QueryRegistry& registry) const {
    const Services wing = wing_;
    // The device a query names and the control parameter it holds (within its range).
    auto deflected = [wing](Configuration& c, const Json& q) {
      const DeviceGeometry device(c, *wing, deviceNamed(c, query::stringArgument(q, "uid")));
      const double p = heldParameter(device, query::numberArgument(q, "control_parameter"));
      return std::make_pair(p, device.motionAt(p));
    };
    // The device's shape at rest moved by its motion at the query's control parameter.
    auto movedShape = [deflected](Configuration& c, const Json& q) {
      const gp_Trsf motion = deflected(c, q).second;
      const TopoDS_Shape& rest = c.shapes().shapeOf(c, query::stringArgument(q, "uid"));
      return rest.Moved(TopLoc_Location(motion));
    };
    registry.add({"control_surface_deflection", "",
                  "uid, control_parameter -> {control_parameter, rotation, matrix}: the device's rigid motion",
                  [deflected](Configuration& c, const Json& q) -> Json {
                    const auto [p, motion] = deflected(c, q);
                    return motionJson(p, motion);
                  }});
    registry.add({"control_surface_bounding_box", "", "uid, control_parameter -> {min, max} of the deflected device",
                  [movedShape](Configuration& c, const Json& q) -> Json {
                    return query::boxAnswer(query::tightBox(movedShape(c, q)));
                  }});
    registry.add(
        {"control_surface_volume", "", "uid, control_parameter -> volume of the deflected device",
         [movedShape](Configuration& c, const Json& q) -> Json { return geometry::enclosedVolume(movedShape(c, q)); }});
    registry.add(
        {"control_surface_surface_area", "", "uid, control_parameter -> area of the deflected device",
         [movedShape](Configuration& c, const Json& q) -> Json { return geometry::areaOf(movedShape(c, q)); }});
  }

  Services wing_;
};

}  // namespace
}  // namespace airshape::controlsurfaces

AIRSHAPE_PLUGIN(airshape::controlsurfaces::ControlSurfacesPlugin)
