#pragma once

#include <string>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>

#include "airshape/model/placement.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// A curve coordinate zeta of [−1, 0] as the share of arc length from a lower side's start.
/// Throws Error naming `where` outside that range.
double lengthShare(double zeta, const std::string& where);

/// A cowl section's profile placed in the nacelle's frame: the lower side from the trailing edge
/// (zeta −1) to the leading edge (zeta 0), the upper side on to the trailing edge (zeta 1).
struct PlacedProfile {
  Handle(Geom_BSplineCurve) lower, upper;
  double angle = 0.0;   ///< the section's turn about the x axis, degrees
  double radius = 0.0;  ///< the section's radial offset (translation z)
  std::string uID;      ///< the section's uID

  /// The point at curve coordinate zeta in [−1, 1] (arc length on each side).
  gp_Pnt at(double zeta) const;
  /// The distance from the leading edge to the middle of the trailing edge.
  double chord() const;
};
PlacedProfile placedProfile(const Configuration& configuration, const schema::NacelleSectionType& section);

/// The cowl's rotation curve between startZeta and endZeta, placed like its reference section;
/// its curve coordinate runs as a lower side's, −1 at its last point and 0 at its first.
Handle(Geom_BSplineCurve) rotationPiece(const Configuration& configuration, const schema::NacelleCowlType& cowl);

}  // namespace airshape::nacelle
