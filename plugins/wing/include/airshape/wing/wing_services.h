#pragma once

#include <string>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace airshape {
class Configuration;
}

namespace airshape::wing {

/// What the wing plugin offers the plugins that build on wings (control surfaces, structure,
/// a third party's): the wing geometry, by uID, in the global frame. It is offered as the
/// service named kWingServices; a plugin that uses it requires the wing plugin and takes it
/// in Plugin::useServices (docs/plugins.md). Errors are airshape::Error naming the node.
class WingServices {
 public:
  virtual ~WingServices() = default;

  /// The surfaces of a wing a point can lie on.
  enum class Surface { Upper, Lower, Chord };

  /// The clean solid of a wing or rotor blade: no cut-outs, devices at rest.
  virtual const TopoDS_Shape& cleanSolid(const Configuration& configuration, const std::string& wingUid) const = 0;

  /// The point at component-segment coordinates (eta, xsi), both in [0, 1], on a surface of
  /// the wing that holds the component segment.
  virtual gp_Pnt componentSegmentPoint(const Configuration& configuration, const std::string& componentSegmentUid,
                                       double eta, double xsi, Surface surface) const = 0;

  /// The point at (eta, xsi) given relative to `referenceUid`: the component segment itself
  /// (or empty: component segment coordinates) or a wing segment of its wing (segment
  /// coordinates), on a surface. Throws Error for any other reference.
  virtual gp_Pnt pointRelativeTo(const Configuration& configuration, const std::string& componentSegmentUid,
                                 const std::string& referenceUid, double eta, double xsi, Surface surface) const = 0;

  /// The segments of a wing or rotor blade by uID, in chain order.
  virtual std::vector<std::string> segmentUids(const Configuration& configuration,
                                               const std::string& wingUid) const = 0;

  /// The point at segment coordinates (eta, xsi), both in [0, 1], of the segment at `segment`
  /// (0-based, chain order) of a wing or rotor blade, on a surface, in the global frame (a
  /// rotor blade's own frame: its transformation, no rotor).
  virtual gp_Pnt segmentPoint(const Configuration& configuration, const std::string& wingUid, std::size_t segment,
                              double eta, double xsi, Surface surface) const = 0;

  /// The wing segments a component segment runs through, from its inner to its outer end.
  virtual std::vector<std::string> componentSegmentSegmentUids(const Configuration& configuration,
                                                               const std::string& componentSegmentUid) const = 0;

  /// The closed solid of the wing segments a component segment runs through: their skins,
  /// blunt trailing-edge strips and the caps at its two ends, what its structure lies in. (The
  /// component segment's own shape, as the reference's, leaves out the strips.)
  virtual const TopoDS_Shape& componentSegmentSolid(const Configuration& configuration,
                                                    const std::string& componentSegmentUid) const = 0;

  /// The upper or the lower skin of a component segment (Surface::Upper or Lower), as faces
  /// in the global frame. A skin shaped by guide curves that no leading-edge guide splits is
  /// one face, returned for both.
  virtual TopoDS_Shape componentSegmentSkin(const Configuration& configuration, const std::string& componentSegmentUid,
                                            Surface surface) const = 0;

  /// An eta that CPACS gives relative to `referenceUid` (the component segment itself, or
  /// one of its wing segments) as the component segment's eta. Throws Error for a reference
  /// that is neither.
  virtual double componentSegmentEta(const Configuration& configuration, const std::string& componentSegmentUid,
                                     const std::string& referenceUid, double eta) const = 0;

  /// The normal of the component segment's mid-plane at `eta`, in the global frame (not
  /// normalised): in the wing's own frame, the chord direction at eta crossed with the
  /// spanwise direction of its leading edge seen from the front (x dropped; eta a share of that
  /// line's length, and on a kink of it the bisector of both sides' directions); it points to
  /// the upper skin.
  virtual gp_Vec midplaneNormal(const Configuration& configuration, const std::string& componentSegmentUid,
                                double eta) const = 0;

  /// The airfoil sides along the wing that holds a component segment, placed in the global
  /// frame: for every segment of the wing in chain order the upper (lower) side of its inner
  /// airfoil, and last the last segment's outer airfoil's. Each side is a B-spline over [0, 1]
  /// whose parameter is xsi (0 at the leading edge); ruled skins run straight between them.
  /// `segmentUids` are the wing's segments in the same order.
  struct AirfoilSides {
    std::vector<Handle(Geom_BSplineCurve)> sides;
    std::vector<std::string> segmentUids;
  };
  virtual AirfoilSides airfoilSides(const Configuration& configuration, const std::string& componentSegmentUid,
                                    Surface surface) const = 0;

  /// A wing airfoil by uID as one closed wire in profile coordinates (x along the chord,
  /// z up): its lower side from the trailing edge to the leading edge, its upper side on to
  /// the trailing edge, and a straight trailing edge where it is blunt.
  virtual TopoDS_Wire airfoilWire(const Configuration& configuration, const std::string& airfoilUid) const = 0;
};

/// The name the wing plugin offers WingServices under; the number is the interface's version.
inline constexpr const char* kWingServices = "airshape.wing.WingServices/6";

}  // namespace airshape::wing
