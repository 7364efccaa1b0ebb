#pragma once

#include <TopoDS_Shape.hxx>

#include "airshape/model/placement.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// The placement of a nacelle section in the nacelle's frame (x along the engine axis), which
/// CPACS gives in cylindrical coordinates (docs/nacelle.md): the profile turned from the x-y
/// into the x-z plane, scaled, rotated, then turned about the x axis by translation/x degrees
/// and moved to axial position translation/y at radius translation/z.
model::Transform sectionTransform(const schema::NacelleSectionType& section);

/// A cowl (fan cowl or core cowl) of one section: its profile revolved about the nacelle's x axis,
/// its inner side between startZetaBlending and endZetaBlending replaced by the rotation curve
/// between startZeta and endZeta, joined to it by straight blending lines. Throws Error naming
/// the CPACS path of what cannot be built; cowls of several sections are not built yet.
TopoDS_Shape cowlSolid(const Configuration& configuration, const schema::NacelleCowlType& cowl);

/// The centre cowl (the spinner or plug): its curve profile, moved along x by xOffset, revolved
/// about the nacelle's x axis and closed by plane discs where it ends off the axis.
TopoDS_Shape centerCowlSolid(const Configuration& configuration, const schema::NacelleCenterCowlType& cowl);

}  // namespace airshape::nacelle
