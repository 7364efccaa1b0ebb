#pragma once

#include <optional>
#include <string>
#include <vector>

#include "airshape/schema/generated/cpacs_model.h"
#include "device_border.h"

namespace airshape {
class Configuration;
}

namespace airshape::controlsurfaces {

/// An airfoil of a device between its borders (`intermediateAirfoils`): placed with its leading
/// edge on the device's leading edge at `eta`, its trailing edge on the device's trailing edge,
/// its z scaled by `scaleZ`.
struct IntermediateAirfoil {
  std::string xpath;
  RelativeCoordinate eta;
  std::string airfoilUid;
  double scaleZ = 1.0;
  double rotX = 90.0, rotZ = 90.0;  ///< degrees; 90 places it in flight direction, upright
};

/// What a device's `wingCutOut` removes from the wing besides the device: the skins aft of
/// these xsi (ahead of them for a leading-edge device), component segment coordinates at the
/// inner and the outer border, between the cut-out's own etas where it gives them (else the
/// device's borders), closed by a straight line across the wing.
struct WingCutOut {
  std::string xpath;
  double upperInner = 1.0, upperOuter = 1.0, lowerInner = 1.0, lowerOuter = 1.0;
  std::optional<RelativeCoordinate> innerEtaLE, innerEtaTE, outerEtaLE, outerEtaTE;
  /// What the element gives that is not applied (spar and rib references, cut-out profiles);
  /// with spar references the skins' xsi are unknown and only the device is cut out.
  std::vector<std::string> notApplied;
  bool skinsKnown = true;
};

/// A control device of a wing as the schema gives it.
struct Device {
  enum class Kind { TrailingEdge, LeadingEdge, Spoiler };
  Kind kind = Kind::TrailingEdge;
  std::string uid;
  std::string xpath;
  const schema::ControlSurfacePathType* path = nullptr;  ///< its steps and hinge points, if given
  std::string parentUid;                                 ///< its component segment, or the device it sits on
  std::string componentSegmentUid;                       ///< the component segment it belongs to
  std::string wingUid;
  bool hasOuterShape = false;  ///< both borders given; without them it has no geometry
  BorderDefinition innerBorder, outerBorder;
  std::vector<IntermediateAirfoil> intermediateAirfoils;  ///< in document order
  std::optional<WingCutOut> wingCutOut;
};

/// The counted devices of a wing in the order of the query protocol (QUERY-components §3.1):
/// its component segments in document order, in each first the trailing-edge devices, then
/// the leading-edge devices. Spoilers are not counted.
std::vector<Device> countedDevicesOf(const schema::WingType& wing);

/// The spoilers of a wing: its component segments in document order, in each its spoilers.
std::vector<Device> spoilersOf(const schema::WingType& wing);

/// The device (spoilers included) with this uID in the first model; throws Error when the uID
/// names no device.
Device deviceNamed(const Configuration& configuration, const std::string& uid);

/// The device (spoilers included) with this uID in any model of the document, for building.
Device deviceInAnyModel(const Configuration& configuration, const std::string& uid);

/// The control parameters of the device's first and last step, in document order
/// (QUERY-components §3.3). Throws Error naming its path when it has no steps.
std::pair<double, double> parameterRangeOf(const Device& device);

/// The protocol's name of a device's kind: trailing_edge_device, leading_edge_device, spoiler.
const char* kindName(Device::Kind kind);

}  // namespace airshape::controlsurfaces
