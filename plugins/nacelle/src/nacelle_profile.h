#pragma once

#include <optional>
#include <string>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// A 2D profile of the nacelle (`nacelleProfiles/nacelleProfile`, `curveProfiles/curveProfile`)
/// drawn in the x-z plane (its y as z): one cubic curve through its points at centripetal
/// parameters. A cowl profile is split at its leading edge (the point farthest from the
/// trailing edge's middle) into the lower side, from the trailing edge to the leading edge, and
/// the upper side, on to the trailing edge, and closed by a straight trailing edge where its ends
/// differ. Zeta, the reference library's curve coordinate, is the share of arc length: −1 at the
/// lower trailing edge, 0 at the leading edge, 1 at the upper trailing edge. A profile given as
/// `cst2D` has its two sides as they are defined (the CST curves of the wing's airfoils), joined
/// at the leading edge.
class NacelleProfile {
 public:
  /// The profile of this uID among the nacelle profiles (or, with `curveProfile`, among the
  /// curve profiles). Throws Error naming `where` when none has it, or naming the profile's path
  /// when it has no points or its CST definition is broken.
  static NacelleProfile named(const Configuration& configuration, const std::string& uid, bool curveProfile,
                              const std::string& where);

  /// The whole curve from its first to its last point.
  const Handle(Geom_BSplineCurve) & whole() const { return whole_; }
  const Handle(Geom_BSplineCurve) & lower() const { return lower_; }
  const Handle(Geom_BSplineCurve) & upper() const { return upper_; }
  /// From the upper side's end to the lower side's start, where they differ.
  std::optional<std::pair<gp_Pnt, gp_Pnt>> trailingEdge() const { return trailingEdge_; }

 private:
  static NacelleProfile fromCst(const schema::Cst2DType& cst, const std::string& xpath);

  Handle(Geom_BSplineCurve) whole_, lower_, upper_;
  std::optional<std::pair<gp_Pnt, gp_Pnt>> trailingEdge_;
};

/// The parameter at which a curve has travelled `share` (0 to 1) of its arc length.
double parameterAtLengthShare(const Handle(Geom_BSplineCurve) & curve, double share);

/// The piece of a curve between two parameters, as a B-spline.
Handle(Geom_BSplineCurve) curvePiece(const Handle(Geom_BSplineCurve) & curve, double from, double to);

}  // namespace airshape::nacelle
