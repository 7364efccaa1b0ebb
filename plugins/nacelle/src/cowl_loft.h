#pragma once

#include <TopoDS_Shape.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// A cowl of several sections around the engine (docs/nacelle.md): the outer surface is a row
/// of Coons patches per sector, one per cell between the sections' outlines (without the lower
/// side's blending part) and the cowl's guides (cowlGuides: at the outline's ends, the leading
/// and trailing edges and the cowl's own guide curves); the inner side is the revolved rotation
/// curve, joined to the outer surface by ruled blending surfaces around the engine.
TopoDS_Shape loftedCowl(const Configuration& configuration, const schema::NacelleCowlType& cowl);

}  // namespace airshape::nacelle
