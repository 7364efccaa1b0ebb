#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>

#include "airshape/schema/generated/cpacs_model.h"
#include "cowl_parts.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// A guide curve of a cowl of several sections: a closed curve around the engine through the
/// point at curve coordinate `zeta` of every section.
struct CowlGuide {
  double zeta;
  Handle(Geom_BSplineCurve) curve;
};

/// The guides of a cowl (docs/nacelle.md): one at each of `requiredZetas` and one at each zeta
/// of the cowl's own guide curves (`guideCurves/nacelleGuideCurve`). From one section to the
/// next (`sections`, in order of their angle, the last followed by the first) a guide turns
/// linearly with the angle while its axial position and radius follow the cubic step
/// 3u² − 2u³ (u the share of the angle) from the one section's point to the next's; a guide
/// curve profile adds its offsets (rY along the axis, scaled by the chord, rZ outwards, scaled
/// by the radius, both interpolated over rX = u). Throws Error naming the CPACS path of a
/// guide that cannot be built.
std::vector<CowlGuide> cowlGuides(const Configuration& configuration, const schema::NacelleCowlType& cowl,
                                  const std::vector<PlacedProfile>& sections, const std::vector<double>& requiredZetas);

}  // namespace airshape::nacelle
