#pragma once

#include <string>
#include <vector>

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

/// Whether a cowl's meridian at a section crosses itself: the loop, in the plane through the
/// engine's axis (axial position and radius), of the section's outline from the trailing edge
/// down its lower side to `startZetaBlending`, over to the inner curve's start (its startZeta:
/// the blending joins by name, as the schema says), along the inner curve, over to
/// `endZetaBlending` and on over the leading edge and the upper side back to the trailing edge.
/// A file whose rotation curve runs backwards makes the blending lines cross.
bool meridianCrossesItself(const PlacedProfile& section, double startZetaBlending, double endZetaBlending,
                           const Handle(Geom_BSplineCurve) & inner);

/// Warns in one line, naming the rotation curve's CPACS path, where the cowl's meridian crosses
/// itself at any of its sections (meridianCrossesItself): the cowl is built as given, a solid
/// that passes through itself.
void warnWhereTheMeridianCrosses(const Configuration& configuration, const schema::NacelleCowlType& cowl,
                                 const std::vector<PlacedProfile>& sections, const Handle(Geom_BSplineCurve) & inner);

/// The cowl's rotation curve from startZeta to endZeta, placed like its reference section; its
/// curve coordinate runs as a lower side's, −1 at its trailing end (the end further along x) and
/// 0 at its leading end, whichever way its points are written.
Handle(Geom_BSplineCurve) rotationPiece(const Configuration& configuration, const schema::NacelleCowlType& cowl);

}  // namespace airshape::nacelle
