#pragma once

#include <string>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>
#include <gp_Vec2d.hxx>

#include "airshape/schema/generated/cpacs_model.h"
#include "line_crossings.h"

namespace airshape::controlsurfaces {

/// An eta or xsi as CPACS gives it: a number relative to a reference (the component segment
/// or one of its wing segments; empty for the component segment).
struct RelativeCoordinate {
  double value = 0.0;
  std::string referenceUid;
};

/// One end of a device's outer shape (its inner or outer border): where its leading and
/// trailing edges lie on the component segment and how its nose is shaped.
struct BorderDefinition {
  enum class Nose {
    Straight,          ///< cut straight across the wing at the leading edge (the device aft)
    StraightBack,      ///< cut straight across the wing at the trailing edge (the device ahead: slats)
    LeadingEdgeShape,  ///< a rounded nose through a point at relHeight between the skins (flaps)
    InnerShape,        ///< a hollow trailing end, rounded through a point between the skins (slats)
    Airfoil,           ///< its own airfoil, scaled to the border's chord
    Panel              ///< the upper skin between the leading and trailing edge, down to relHeight (spoilers)
  };
  std::string xpath;
  std::string missing;  ///< the required element the border lacks (then nothing else is set)
  RelativeCoordinate etaLE, etaTE;
  double xsiLE = 0.0, xsiTE = 1.0;
  Nose nose = Nose::Straight;
  /// For a shaped nose: where the rounded edge meets the upper and the lower skin and where
  /// its middle point lies, as shares of the border's chord from its trailing edge (1 is the
  /// leading edge), and the middle point's height between the skins (for a panel: the height
  /// of its lower side). A straight back (slats) meets the skins at the component segment xsi
  /// `xsiUpperSkin` and `xsiLowerSkin`.
  double xsiUpperSkin = 1.0, xsiLowerSkin = 1.0, xsiMiddle = 1.0, relHeight = 0.5;
  std::string airfoilUid;
  double airfoilScaleZ = 1.0;
};

BorderDefinition borderOf(const schema::ControlSurfaceBorderTrailingEdgeType& border);
BorderDefinition borderOf(const schema::ControlSurfaceBorderLeadingEdgeType& border);
BorderDefinition borderOf(const schema::ControlSurfaceBorderSpoilerType& border);

/// The plane a border is drawn in: through its leading-edge point `origin`, spanned by the
/// chord direction `x` (towards its trailing-edge point) and `y`, the component segment's
/// upward direction made normal to the chord; `z` is normal to the plane.
struct BorderPlane {
  gp_Pnt origin;
  gp_Vec x, y, z;
  double chord = 0.0;  ///< distance of the leading- and trailing-edge points

  BorderPlane(const gp_Pnt& leadingEdge, const gp_Pnt& trailingEdge, const gp_Vec& up);
  gp_Pnt at(double u, double v) const { return origin.Translated(u * x + v * y); }
};

/// A border's outline in its plane as far as it leaves the wing: the part inside the wing and
/// the points and directions it leaves by. Outside the wing it is closed together with the
/// device's other outlines (outline_closing.h), so that the ruled solid between them cuts the
/// device out of the wing.
struct BorderOutline {
  enum class Kind {
    Across,  ///< a straight line across the wing from `lower` to `upper`
    Shaped,  ///< the rounded edge `shaped` from `lower` to `upper`
    Panel,   ///< a spoiler's panel: its lower side inside the wing from `lower` (its back) to `upper` (its front)
    Airfoil  ///< the border's own airfoil, closed in itself (`airfoil`)
  };
  BorderOutline(Kind outlineKind, const BorderPlane& borderPlane) : kind(outlineKind), plane(borderPlane) {}

  Kind kind;
  BorderPlane plane;
  TopoDS_Wire airfoil;
  TopoDS_Edge shaped;
  gp_Pnt2d lower, upper;    ///< where the outline leaves the wing, in the plane's coordinates
  gp_Vec2d upOut, downOut;  ///< the directions it leaves `upper` and `lower` along, outwards
  /// Where it closes beyond the wing along the plane's x, in chords: aft (> 0) or ahead (< 0);
  /// a panel closes above the wing only.
  double reach = 0.0;
  /// How far from the chord line the outline closes when closed on its own.
  double height = 0.0;
};

/// The outline of a border. `wing` finds where lines meet the clean wing solid's skins;
/// `airfoil` the border's own airfoil in profile coordinates (Nose::Airfoil only). Throws
/// Error naming the border's CPACS path when the border does not cross the wing's skins.
BorderOutline borderOutline(const BorderDefinition& border, const BorderPlane& plane, LineCrossings& wing,
                            const TopoDS_Wire& airfoil);

/// The outline of a skin cut-out in a border plane: the wing section aft of (`aft`; else ahead
/// of) the straight line from the upper skin at `upperShare` of the chord (from the plane's
/// origin) to the lower skin at `lowerShare`. Throws Error naming `xpath` when the lines at
/// those shares do not cross both skins.
BorderOutline skinCutOutOutline(const BorderPlane& plane, LineCrossings& wing, double upperShare, double lowerShare,
                                bool aft, const std::string& xpath);

}  // namespace airshape::controlsurfaces
