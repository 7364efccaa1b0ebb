#include "component_segments.h"

#include "airshape/configuration.h"
#include "airshape/wing/wing_list.h"

namespace airshape::structure {

std::vector<WingComponentSegment> everyComponentSegment(const Configuration& configuration) {
  std::vector<WingComponentSegment> all;
  for (std::size_t model = 0; model < model::modelCount(configuration); ++model)
    for (const schema::WingType* wing : wing::wingsOf(configuration, model)) {
      if (!wing->componentSegments) continue;
      for (const auto& componentSegment : wing->componentSegments->componentSegment)
        all.push_back({wing, &componentSegment});
    }
  return all;
}

namespace {

/// Adds the structure of each device of a list (trailing-edge devices, ...) that has one.
template <typename Devices>
void addDeviceStructures(const Devices& devices, const WingComponentSegment& host, std::vector<StructureHost>& all) {
  for (const auto& device : devices)
    if (device.structure) all.push_back({host.wing, host.componentSegment, &*device.structure, device.uID});
}

}  // namespace

std::vector<StructureHost> everyStructure(const Configuration& configuration) {
  std::vector<StructureHost> all;
  for (const WingComponentSegment& host : everyComponentSegment(configuration)) {
    const schema::ComponentSegmentType& componentSegment = *host.componentSegment;
    if (componentSegment.structure) all.push_back({host.wing, host.componentSegment, &*componentSegment.structure, ""});
    if (!componentSegment.controlSurfaces) continue;
    const schema::ControlSurfacesType& devices = *componentSegment.controlSurfaces;
    if (devices.trailingEdgeDevices) addDeviceStructures(devices.trailingEdgeDevices->trailingEdgeDevice, host, all);
    if (devices.leadingEdgeDevices) addDeviceStructures(devices.leadingEdgeDevices->leadingEdgeDevice, host, all);
    if (devices.spoilers) addDeviceStructures(devices.spoilers->spoiler, host, all);
  }
  return all;
}

}  // namespace airshape::structure
