#pragma once

#include <string>

#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>

#include "structure_frame.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// The plane, in the wing frame, of rib `number` (from 1) of a ribs definition, from its built
/// faces. Throws Error naming `where` when the definition has no such plane rib.
gp_Pln ribPlane(const Configuration& configuration, const StructureFrame& frame, const std::string& ribsUid,
                long long number, const std::string& where);

/// The point at share xsi along rib `number` of a ribs definition, from where the rib's plane
/// crosses its start line (`ribStart`: the leading or trailing edge or a spar's midplane line) to
/// where it crosses its end line, on the chord surface (wing frame): a spar position on a rib.
gp_Pnt pointOnRib(const Configuration& configuration, const StructureFrame& frame, const std::string& ribsUid,
                  long long number, double xsi, const std::string& where);

}  // namespace airshape::structure
