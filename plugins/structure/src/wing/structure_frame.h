#pragma once

#include <optional>
#include <string>

#include <Eigen/Geometry>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/geometry/polyline.h"
#include "airshape/model/placement.h"
#include "airshape/wing/wing_services.h"
#include "spar_list.h"
#include "structure_services.h"

namespace airshape::structure {

/// A component segment as its structure is defined on it: in the wing's own frame (where the
/// schema's "up", "global y" and the reference library's structure live), with the lines and
/// normals rib positions refer to, and the solid structure is cut from (in the global frame).
///
/// The structure of a control device (`deviceUid`) lives in the device's own coordinates
/// instead: eta from its inner to its outer border, xsi from its leading to its trailing edge
/// (DeviceServices), whatever component segment or wing segment an eta names as its reference;
/// its leading and trailing edge are the device's, its solid and skins the device's at rest.
class StructureFrame {
 public:
  StructureFrame(const Configuration& configuration, const StructureServices& services, std::string componentSegmentUid,
                 std::string wingUid, std::string deviceUid);

  gp_Pnt toGlobal(const gp_Pnt& p) const { return model::apply(toGlobal_, p); }
  gp_Vec toGlobal(const gp_Vec& v) const;
  gp_Pnt toWing(const gp_Pnt& p) const { return model::apply(toWing_, p); }
  gp_Vec toWing(const gp_Vec& v) const;

  /// A point on the chord surface at (eta, xsi) relative to the component segment or one of
  /// its wing's segments, in the wing frame.
  gp_Pnt chordPoint(const std::string& referenceUid, double eta, double xsi) const;
  /// The eta of the frame (the component segment's, or the device's own) of an eta given
  /// relative to `referenceUid`.
  double frameEta(const std::string& referenceUid, double eta) const;
  /// The component segment eta of a point on (or near) its chord surface, in the wing frame.
  double etaOf(const gp_Pnt& point) const;
  /// The unit normal of the chord surface at eta (towards the upper skin), in the wing frame.
  gp_Vec midplaneNormal(double eta) const;
  /// The one direction across the wing that cells are cut along (wing frame, unit, towards the
  /// upper skin): the root chord crossed with the leading edge from root to tip seen from the
  /// front (x dropped), as the reference library's cells are cut. It is the midplane normal of
  /// a wing without twist whose leading edge is straight seen from the front; on a twisted blade
  /// or a wing with a kink in dihedral the cells' sides do not turn with the sections.
  gp_Vec cellDirection() const;
  /// The component segment etas of the sections it runs through (0, those between its wing
  /// segments, 1).
  std::vector<double> sectionEtas() const;
  /// From the lower to the upper skin at component segment (eta, xsi), in the wing frame (not
  /// normalised): in a section's plane, square to its chord.
  gp_Vec thicknessDirection(double eta, double xsi) const;
  /// The up direction at a spar position at `eta` (wing frame, unit): the wing's z axis,
  /// except at a section (the root, the tip, a section between wing segments), where it is the
  /// line in the section's plane square to the wing's x axis, as the reference library's ribs
  /// starting at such a spar position show (in a device: the wing's z axis throughout).
  gp_Vec uprightAtSparPosition(double eta) const;
  /// The direction in which eta grows at eta (wing frame, unit): the leading edge seen from
  /// the front (x dropped), along which the component segment's eta is measured.
  gp_Vec etaDirection(double eta) const;
  /// The leading or trailing edge: straight from section to section, in the wing frame (the
  /// trailing edge through `sectionTrailingEdge`).
  geometry::Polyline leadingEdge() const { return edgeLine(false); }
  geometry::Polyline trailingEdge() const { return edgeLine(true); }
  /// The line between two chord surface points (wing frame): straight within a wing segment,
  /// broken where its vertical plane crosses a section's line from the leading edge to
  /// `sectionTrailingEdge`.
  geometry::Polyline midplaneLine(const gp_Pnt& from, const gp_Pnt& to) const;
  /// The midplane line through a spar segment's positions, in the wing frame.
  geometry::Polyline sparLine(const SparSegment& spar) const;
  /// The leading edge, the trailing edge or a spar's midplane line (wing frame), by name (a
  /// spar segment's uID); an error names `where` when the name is none of them.
  geometry::Polyline lineNamed(const std::string& name, const std::string& where) const;
  /// A spar position's point on the chord surface (wing frame): by eta and xsi, on a rib, or
  /// at a share of the length of a line (`lineNamed`).
  gp_Pnt positionPoint(const SparPosition& position) const;

  /// The closed solid of the component segment's wing segments (or the device's solid; global
  /// frame), and the size of a box that holds it (a length that surely reaches across it).
  const TopoDS_Shape& solid() const;
  double reach() const;
  /// The upper or the lower skin structure is bounded by (global frame): the component
  /// segment's, or the device's faces named upper or lower.
  TopoDS_Shape skin(bool upper) const;
  /// The upper or the lower skin of the component segment (global frame), also for a device's
  /// structure: the untrimmed skin a device is cut out of.
  TopoDS_Shape componentSegmentSkin(bool upper) const;
  /// For the structure of a device cut out of its wing, the simple solid that cuts it
  /// (DeviceServices::cutter); nothing for a component segment's structure or a device with
  /// its own airfoil.
  std::optional<TopoDS_Shape> deviceCutter() const;

  const std::string& componentSegmentUid() const { return componentSegmentUid_; }
  bool inDevice() const { return !deviceUid_.empty(); }
  /// What structure lies in, for messages: "its component segment" or "its device".
  const char* hostName() const { return inDevice() ? "its device" : "its component segment"; }
  const wing::WingServices& wing() const { return services_.wing; }

 private:
  geometry::Polyline edgeLine(bool trailing) const;
  /// A section's trailing edge point as the lines along the span take it: the upper skin's
  /// (at a blunt trailing edge its upper corner, not the chord's end), as the reference
  /// library draws its trailing edge and spar lines; D250's ribs set along its kinked mid spar
  /// are where the reference puts them only so (5e-5 m off along the spar with the chord's end).
  /// In a device: its chord's end.
  gp_Pnt sectionTrailingEdge(const std::string& segmentUid, double eta) const;
  /// The component segment coordinates of a point in the frame's (eta, xsi).
  std::pair<double, double> componentSegmentCoordinates(double eta, double xsi) const;

  const Configuration& configuration_;
  StructureServices services_;
  std::string componentSegmentUid_, deviceUid_;
  model::Transform toGlobal_, toWing_;
};

}  // namespace airshape::structure
