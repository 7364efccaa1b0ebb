#pragma once

#include "airshape/named_shape.h"
#include "cell_list.h"
#include "structure_services.h"

namespace airshape::structure {

/// The skin patch of a cell (QUERY-components §1, `wing_cell`): the part of its shell's skin
/// (the component segment's upper or lower skin) inside the four vertical planes (along the
/// wing's z axis) through its corners on the chord surface. The corners are the cell's leading
/// and trailing edge (xsi1 at the inner border, xsi2 at the outer, or where a spar's midplane
/// line crosses the border's chord) at its inner and outer border (eta1 at the leading edge,
/// eta2 at the trailing edge). Faces are named "<uID>/skin". Throws Error naming the CPACS path
/// of what cannot be built. A border on a rib (ribDefinitionUID, ribNumber) has its corners
/// where the rib's plane crosses the leading and trailing edge's lines on the chord surface (an
/// xsi, or a spar's midplane line). A cell bounded by contour coordinates is contourCellSkin's
/// (not built in a control device).
NamedShape cellSkin(const Configuration& configuration, const StructureServices& services, const WingCell& cell);

}  // namespace airshape::structure
