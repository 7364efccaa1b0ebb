#pragma once

#include <string>

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

namespace airshape {
class Configuration;
}

namespace airshape::controlsurfaces {

/// What the control-surfaces plugin offers the plugins that build inside control devices (the
/// structure plugin's spars, ribs and cells of a flap, slat, aileron or spoiler): the device's
/// own coordinates. Offered as the service named kDeviceServices; a plugin that uses it requires
/// the controlsurfaces plugin (docs/plugins.md). The device at rest itself is a component shape
/// like any other (ComponentShapes, by the device's uID). Errors are airshape::Error naming the
/// node.
class DeviceServices {
 public:
  virtual ~DeviceServices() = default;

  /// A point in the component segment's coordinates (eta, xsi).
  struct ComponentSegmentPoint {
    double eta = 0.0, xsi = 0.0;
  };

  /// The point of the device's chord surface at its own coordinates (eta from its inner
  /// border, 0, to its outer border, 1; xsi from its leading edge, 0, to its trailing edge, 1),
  /// in the global frame: on the straight line from its leading to its trailing edge at eta.
  /// An edge within the wing runs straight from border to border (the schema's remarks on
  /// control surfaces); an edge on the wing's leading or trailing edge follows it.
  virtual gp_Pnt chordPoint(const Configuration& configuration, const std::string& deviceUid, double eta,
                            double xsi) const = 0;

  /// About where the device's own coordinates lie in the coordinates of the component segment
  /// that holds it (bilinear between the four corners of its outer shape), for taking the
  /// wing's directions there.
  virtual ComponentSegmentPoint componentSegmentPoint(const Configuration& configuration, const std::string& deviceUid,
                                                      double eta, double xsi) const = 0;

  /// The ruled solid between the device's inner and outer border (global frame) that cuts it
  /// out of its wing: the device at rest is this solid's common with the clean wing, or, when
  /// `ownAirfoil`, this solid itself (a device with its own airfoil). Where the wing's skins
  /// give the wing's section directly, structure inside the device is that section cut by this
  /// simple solid instead of by the device's trimmed faces.
  struct Cutter {
    TopoDS_Shape solid;
    bool ownAirfoil = false;
  };
  virtual Cutter cutter(const Configuration& configuration, const std::string& deviceUid) const = 0;
};

/// The service name; the number changes whenever DeviceServices does.
inline constexpr const char* kDeviceServices = "airshape.controlsurfaces.DeviceServices/2";

}  // namespace airshape::controlsurfaces
