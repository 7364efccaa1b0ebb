#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/named_shape.h"

namespace airshape::structure {

class StructureFrame;

/// One border of a wing fuel tank as the direct construction takes it (global frame): a spar's
/// wall, through its positions' points along their up directions (unit), or a rib's plane
/// (a point of it, its normal and its up direction). `name` names the tank's faces on it.
struct TankWall {
  std::string name;
  bool spar = false;
  std::vector<gp_Pnt> points;
  std::vector<gp_Vec> ups;
  gp_Pnt point;
  gp_Vec normal, up;
};

/// The tank enclosed by its walls, listed in order around it, made from the component segment's
/// skins without intersecting surfaces: the loop of lines where consecutive walls meet (and
/// through a spar's positions between), the skins split along that loop (skin_split.h), the
/// walls' faces between the skins (ruled_section.h), sewn into one solid; `inside` tells the
/// skin pieces of the tank (a point of each, global frame). Faces on a wall are
/// named `<tank>/<wall's name>`, on the skins `<tank>/<component segment>/upper` and `/lower`.
/// Nothing where that does not apply (walls that do not meet each next one in a line, a twisted
/// piece of a spar's wall in the loop, skins the direct constructions do not take): the caller
/// then splits the component segment's solid.
std::optional<NamedShape> tankFromSkins(const StructureFrame& frame, const std::vector<TankWall>& walls,
                                        const std::function<bool(const gp_Pnt&)>& inside, const std::string& tankUid);

}  // namespace airshape::structure
