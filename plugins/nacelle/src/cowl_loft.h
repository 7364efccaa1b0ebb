#pragma once

#include <TopoDS_Shape.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// A cowl of several sections around the engine (docs/nacelle.md): between two sections that
/// follow each other in angle, every point of the profile (by its curve coordinate zeta) runs
/// along the reference library's guide curve: its angle linearly, its axial position and radius
/// by the cubic step 3u² − 2u³ from one section's to the next's. The outer surface is interpolated
/// through that motion sector by sector, without the lower side's blending part; the inner side
/// is the revolved rotation curve, joined to the outer surface by ruled blending surfaces.
TopoDS_Shape loftedCowl(const Configuration& configuration, const schema::NacelleCowlType& cowl);

}  // namespace airshape::nacelle
