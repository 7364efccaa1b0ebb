#pragma once

#include "airshape/named_shape.h"
#include "airshape/wing/wing_services.h"
#include "cell_list.h"

namespace airshape::structure {

/// Whether the cell's four borders are contour coordinates. Throws Error naming the cell when
/// only some of them are: a contour coordinate does not combine with an eta, xsi, spar or rib.
bool boundedByContourCoordinates(const WingCell& cell);

/// The skin patch of a cell bounded by contour coordinates (docs/structure.md). The skin of its
/// shell is the component segment's upper or lower skin, one face per wing segment. Spanwise,
/// 0 is the inner end of the first face and 1 the outer end of the last; each face takes the
/// share of its spanwise parameter range in the sum of them all (with our ruled segments, one
/// equal share per wing segment, and the segment's eta inside it). Chordwise, 0 is the leading
/// edge and 1 the trailing edge of the face in its chordwise parameter (with our segments, the
/// airfoil side's xsi). The cell is the skin's faces trimmed to these parameter ranges, named
/// "<uID>/skin". Throws Error naming the CPACS path when the skin is not made of such faces.
NamedShape contourCellSkin(const Configuration& configuration, const wing::WingServices& wing, const WingCell& cell);

}  // namespace airshape::structure
