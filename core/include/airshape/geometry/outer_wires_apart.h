#pragma once

#include <vector>

#include <TopoDS_Face.hxx>

namespace airshape::geometry {

/// A face as faces whose wires are nested as OCCT expects: where the face has more than one
/// wire and OCCT's check finds two of them outer ("invalid imbrication of wires", as a Boolean
/// common makes of a plane face on rare inputs), one face per outer wire with the holes inside
/// it (OCCT's shape healing splits it); any other face as it is.
std::vector<TopoDS_Face> outerWiresApart(const TopoDS_Face& face);

}  // namespace airshape::geometry
