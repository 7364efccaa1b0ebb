#pragma once

#include <string>
#include <vector>

#include <Geom_BSplineCurve.hxx>

#include "airshape/geometry/curve_network.h"
#include "airshape/model/guide_curves.h"
#include "airshape/model/placement.h"
#include "fuselage_profile.h"

namespace airshape::fuselage {

/// A profile where a fuselage places it: the global curve, and how it got there.
struct PlacedProfile {
  Handle(Geom_BSplineCurve) curve;
  model::Transform transform;
  const FuselageProfile* profile = nullptr;
  std::string elementUid;  ///< for errors
};

/// The guide curves of a fuselage and where they cross its profiles.
struct FuselageGuides {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  std::vector<std::string> uids;       ///< per guide: its root's uID, for errors
  geometry::KnownCrossings crossings;  ///< profiles in chain order, guides as in `curves`
  /// Per guide: where it starts on the first profile (its relative circumference, or its
  /// profile parameter with the reference's fromParameter).
  std::vector<double> startPositions;
  /// Per guide and section: whether it runs through the section inside one part (C2).
  std::vector<std::vector<bool>> smoothAt;
};

/// The fuselage's guide curves (CONVENTIONS §9) over its placed profiles in chain order:
/// relative circumference is the share of the global profile's length from its start
/// (the closing edge of a half profile included), the guide profiles' alpha runs along
/// global z, and their scale is each profile's guideScale.
FuselageGuides fuselageGuideCurves(const schema::CpacsType& cpacs, const std::vector<PlacedProfile>& sections,
                                   const std::vector<const schema::GuideCurvesType*>& perSegment);

}  // namespace airshape::fuselage
