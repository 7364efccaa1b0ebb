#include "device_services.h"

#include "airshape/configuration.h"
#include "device_geometry.h"
#include "device_list.h"

namespace airshape::controlsurfaces {

namespace {

class DeviceCoordinates final : public DeviceServices {
 public:
  explicit DeviceCoordinates(std::shared_ptr<const wing::WingServices> wing) : wing_(std::move(wing)) {}

  gp_Pnt chordPoint(const Configuration& configuration, const std::string& deviceUid, double eta,
                    double xsi) const override {
    return DeviceGeometry(configuration, *wing_, deviceInAnyModel(configuration, deviceUid)).ownChordPoint(eta, xsi);
  }

  ComponentSegmentPoint componentSegmentPoint(const Configuration& configuration, const std::string& deviceUid,
                                              double eta, double xsi) const override {
    const DeviceGeometry device(configuration, *wing_, deviceInAnyModel(configuration, deviceUid));
    const auto [csEta, csXsi] = device.componentSegmentCoordinates(eta, xsi);
    return {csEta, csXsi};
  }

  Cutter cutter(const Configuration& configuration, const std::string& deviceUid) const override {
    const DeviceGeometry device(configuration, *wing_, deviceInAnyModel(configuration, deviceUid));
    return {device.cutter().shape, device.device().innerBorder.nose == BorderDefinition::Nose::Airfoil};
  }

 private:
  std::shared_ptr<const wing::WingServices> wing_;
};

}  // namespace

std::shared_ptr<const DeviceServices> makeDeviceServices(std::shared_ptr<const wing::WingServices> wing) {
  return std::make_shared<DeviceCoordinates>(std::move(wing));
}

}  // namespace airshape::controlsurfaces
