#pragma once

#include <BRepAlgoAPI_Common.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "airshape/named_shape.h"
#include "airshape/wing/wing_services.h"
#include "device_list.h"

namespace airshape {
class Configuration;
}

namespace airshape::controlsurfaces {

/// The geometry of one device, from the wing it lies in (through the wing plugin's public
/// interface): its shape at rest and its rigid motion at any control parameter.
class DeviceGeometry {
 public:
  DeviceGeometry(const Configuration& configuration, const wing::WingServices& wing, Device device);

  /// The device at rest (QUERY-components §3.2): the clean wing cut by the ruled solid between
  /// its inner and outer border; a border with its own airfoil gives that solid itself. Its
  /// faces are named "<uID>/upper", "lower", "leading edge" (a slat's "trailing edge"),
  /// "trailing edge", "inner side", "outer side" (docs/controlsurfaces.md).
  /// Throws Error naming the device's CPACS path when it cannot be built.
  NamedShape atRest() const;

  /// The ruled solid between the two borders that cuts the device out of the wing, its
  /// faces named "<uID>/inner side", "<uID>/outer side" and, between them, as the face of the
  /// device they become (a flap's "leading edge", a slat's "trailing edge", a spoiler's
  /// "lower", an own airfoil's "skin").
  NamedShape cutter() const;

  /// What the wing loses besides the device when the device moves (its `wingCutOut`): the
  /// ruled solid between the skin cut-out outlines at the cut-out's inner and outer border;
  /// a null shape for a device without one (or one whose skins are given by spars). Says in a
  /// warning what of the element is not applied.
  TopoDS_Shape skinCutOut() const;

  /// The device's rigid motion at a control parameter within the range of its steps
  /// (QUERY-components §3.4); outside the range, an error.
  gp_Trsf motionAt(double controlParameter) const;

  /// The control parameters of the first and the last step (QUERY-components §3.3).
  std::pair<double, double> parameterRange() const;

  /// Where the device's own (eta, xsi) lie in its component segment's coordinates: bilinear
  /// between its borders' leading- and trailing-edge points (DeviceServices).
  std::pair<double, double> componentSegmentCoordinates(double eta, double xsi) const;
  /// The point of the device's own chord surface at its (eta, xsi) (DeviceServices::chordPoint).
  gp_Pnt ownChordPoint(double eta, double xsi) const;

  const Device& device() const { return device_; }

 private:
  /// The outlines the cutter is ruled through: its borders' and, between them, its
  /// intermediate airfoils' (from the inner border outwards), found once per configuration;
  /// `size` is a length the size of the device (its borders' chords and their distance).
  struct Outlines {
    TopoDS_Wire inner, outer;
    std::vector<TopoDS_Wire> between;
    double size = 0.0;
  };
  Outlines outlines() const;
  /// Throws Error naming the outer shape where the borders' chords cross inside the wing (in
  /// component segment eta and xsi): the device between them would fold through itself.
  void checkBordersApart() const;
  /// The cutter, built.
  NamedShape ruledCutter() const;
  /// The Boolean common of the wing and the cutter: exact, or, where that fails or is flawed,
  /// with OCCT's fuzzy tolerance and a warning.
  std::unique_ptr<BRepAlgoAPI_Common> cutOutOf(const TopoDS_Shape& wing, const TopoDS_Shape& cutter) const;
  /// The device at rest made from the wing's skins without a Boolean operation
  /// (device_from_skins.h), where its borders are straight outlines; nothing elsewhere.
  std::optional<NamedShape> fromWingSkins() const;
  /// A border point on the component segment's chord surface.
  gp_Pnt chordPoint(const RelativeCoordinate& eta, double xsi, const std::string& xpath) const;
  /// The component-segment eta of an eta given relative to a reference (at `xpath`).
  double componentSegmentEta(const RelativeCoordinate& eta, const std::string& xpath) const;
  /// The plane a border is drawn in (through its leading- and trailing-edge points).
  BorderPlane borderPlaneOf(const BorderDefinition& border) const;
  /// The component segment's upward direction: its inner chord crossed with its leading edge.
  gp_Vec upward() const;
  /// A border's outline in its plane; `wing` meets lines with the clean wing.
  BorderOutline borderOutlineOf(const BorderDefinition& border, const BorderPlane& plane, LineCrossings& wing) const;
  /// The wires of the intermediate airfoils, from the inner border outwards, each in the plane
  /// between the borders' planes at its eta.
  std::vector<TopoDS_Wire> intermediateWires(const BorderPlane& inner, const BorderPlane& outer,
                                             LineCrossings& wing) const;
  /// A hinge point at rest: between the skins at the hinge's xsi on the border's leading
  /// edge, in the global frame without the wing's parent translation (as the reference);
  /// `skins` meet lines with the component segment's upper and lower skin.
  gp_Pnt hingePoint(const schema::ControlSurfaceHingePointType& hinge, const BorderDefinition& border,
                    const char* which, const std::array<LineCrossings*, 2>& skins) const;

  const Configuration& configuration_;
  const wing::WingServices& wing_;
  Device device_;
};

}  // namespace airshape::controlsurfaces
