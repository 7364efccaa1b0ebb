#pragma once

#include <string>
#include <vector>

#include <gp_Pnt2d.hxx>

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A sheet of a structural profile: the straight piece between two points of the profile's
/// plane (x, y), after the structural element's 2D transformation.
struct ProfileSheet {
  std::string uid;
  gp_Pnt2d from, to;
};

/// The cross section of a profile-based structural element
/// (vehicles/structuralElements/profileBasedStructuralElements) by uID: the sheets of the
/// `structuralProfile2D` it names (profiles/structuralProfiles), each point scaled, turned by the
/// rotation's z (degrees) and moved by the element's `transformation`. Throws Error naming
/// `where` for an element that names nothing, and naming the element for one that gives no
/// explicit cross section (a standard profile, which the schema draws only in a picture, or
/// global beam properties) or whose sheets name points the profile lacks.
std::vector<ProfileSheet> structuralProfileSheets(const Configuration& configuration, const std::string& elementUid,
                                                  const std::string& where);

}  // namespace airshape::structure
