#include "device_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/placement.h"
#include "airshape/wing/wing_list.h"

namespace airshape::controlsurfaces {

namespace {

std::optional<RelativeCoordinate> etaOf(const schema::Child<schema::EtaIsoLineType>& eta) {
  if (!eta) return std::nullopt;
  return RelativeCoordinate{eta->eta, eta->referenceUID};
}

WingCutOut wingCutOutOf(const schema::ControlSurfaceWingCutOutType& node) {
  WingCutOut cutOut;
  cutOut.xpath = node.xpath;
  auto skin = [&](const schema::Child<schema::ControlSurfaceSkinCutOutType>& side, const char* name, double& inner,
                  double& outer) {
    if (side && side->xsiInnerBorder && side->xsiOuterBorder) {
      inner = *side->xsiInnerBorder;
      outer = *side->xsiOuterBorder;
    } else {
      cutOut.skinsKnown = false;
      cutOut.notApplied.push_back(std::string(name) + " by spar");
    }
  };
  skin(node.upperSkin, "upperSkin", cutOut.upperInner, cutOut.upperOuter);
  skin(node.lowerSkin, "lowerSkin", cutOut.lowerInner, cutOut.lowerOuter);
  auto border = [&](const schema::Child<schema::ControlSurfaceSkinCutOutBorderType>& side, const char* name,
                    std::optional<RelativeCoordinate>& le, std::optional<RelativeCoordinate>& te) {
    if (!side) return;
    le = etaOf(side->etaLE);
    te = etaOf(side->etaTE);
    if (!le) cutOut.notApplied.push_back(std::string(name) + " by rib");
  };
  border(node.innerBorder, "innerBorder", cutOut.innerEtaLE, cutOut.innerEtaTE);
  border(node.outerBorder, "outerBorder", cutOut.outerEtaLE, cutOut.outerEtaTE);
  if (node.cutOutProfileControlPoint || node.cutOutProfiles) cutOut.notApplied.push_back("cut-out profiles");
  return cutOut;
}

template <class Node>
Device deviceOf(const Node& node, Device::Kind kind, const schema::WingType& wing,
                const schema::ComponentSegmentType& segment) {
  Device device;
  device.kind = kind;
  device.uid = node.uID;
  device.xpath = node.xpath;
  device.path = node.path ? &*node.path : nullptr;
  device.parentUid = node.parentUID;
  device.componentSegmentUid = segment.uID;
  device.wingUid = wing.uID;
  device.hasOuterShape = node.outerShape && node.outerShape->innerBorder && node.outerShape->outerBorder;
  if (device.hasOuterShape) {
    device.innerBorder = borderOf(*node.outerShape->innerBorder);
    device.outerBorder = borderOf(*node.outerShape->outerBorder);
    if (node.outerShape->intermediateAirfoils)
      for (const auto& airfoil : node.outerShape->intermediateAirfoils->intermediateAirfoil)
        device.intermediateAirfoils.push_back(
            {airfoil.xpath,
             {airfoil.eta ? airfoil.eta->eta : 0.0, airfoil.eta ? airfoil.eta->referenceUID : std::string()},
             airfoil.airfoilUID,
             airfoil.scalZ,
             airfoil.rotX,
             airfoil.rotZ});
  }
  if (node.wingCutOut) device.wingCutOut = wingCutOutOf(*node.wingCutOut);
  return device;
}

/// Every device of a wing, spoilers too, in the protocol's order (spoilers after the others
/// of their component segment).
std::vector<Device> allDevicesOf(const schema::WingType& wing, bool withSpoilers) {
  std::vector<Device> devices;
  if (!wing.componentSegments) return devices;
  for (const auto& segment : wing.componentSegments->componentSegment) {
    if (!segment.controlSurfaces) continue;
    const schema::ControlSurfacesType& surfaces = *segment.controlSurfaces;
    if (surfaces.trailingEdgeDevices)
      for (const auto& device : surfaces.trailingEdgeDevices->trailingEdgeDevice)
        devices.push_back(deviceOf(device, Device::Kind::TrailingEdge, wing, segment));
    if (surfaces.leadingEdgeDevices)
      for (const auto& device : surfaces.leadingEdgeDevices->leadingEdgeDevice)
        devices.push_back(deviceOf(device, Device::Kind::LeadingEdge, wing, segment));
    if (withSpoilers && surfaces.spoilers)
      for (const auto& device : surfaces.spoilers->spoiler)
        devices.push_back(deviceOf(device, Device::Kind::Spoiler, wing, segment));
  }
  return devices;
}

}  // namespace

std::vector<Device> countedDevicesOf(const schema::WingType& wing) { return allDevicesOf(wing, false); }

std::vector<Device> spoilersOf(const schema::WingType& wing) {
  std::vector<Device> spoilers;
  for (const Device& device : allDevicesOf(wing, true))
    if (device.kind == Device::Kind::Spoiler) spoilers.push_back(device);
  return spoilers;
}

Device deviceNamed(const Configuration& configuration, const std::string& uid) {
  for (const schema::WingType* wing : wing::wingsOf(configuration))
    for (const Device& device : allDevicesOf(*wing, true))
      if (device.uid == uid) return device;
  throw Error(ErrorCode::InvalidArgument, "no control surface with uID '" + uid + "'");
}

Device deviceInAnyModel(const Configuration& configuration, const std::string& uid) {
  // Cached: the structure inside a device asks for its coordinates point by point.
  return *configuration.cache().obtain<Device>("device:" + uid, [&] {
    for (std::size_t model = 0; model < model::modelCount(configuration); ++model)
      for (const schema::WingType* wing : wing::wingsOf(configuration, model))
        for (const Device& device : allDevicesOf(*wing, true))
          if (device.uid == uid) return std::make_shared<const Device>(device);
    throw Error(ErrorCode::InvalidArgument, "no control surface with uID '" + uid + "'");
  });
}

std::pair<double, double> parameterRangeOf(const Device& device) {
  if (device.path == nullptr || !device.path->steps || device.path->steps->step.empty())
    throw Error(ErrorCode::InvalidModel, "the control surface has no path steps", {}, device.xpath + "/path");
  const auto& steps = device.path->steps->step;
  for (const auto& step : steps) model::finite(step.controlParameter, step.xpath + "/controlParameter");
  return {steps[0].controlParameter, steps[steps.size() - 1].controlParameter};
}

const char* kindName(Device::Kind kind) {
  switch (kind) {
    case Device::Kind::TrailingEdge:
      return "trailing_edge_device";
    case Device::Kind::LeadingEdge:
      return "leading_edge_device";
    default:
      return "spoiler";
  }
}

}  // namespace airshape::controlsurfaces
