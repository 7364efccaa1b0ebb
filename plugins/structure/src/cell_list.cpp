#include "cell_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "component_segments.h"

namespace airshape::structure {

WingCell wingCellNamed(const Configuration& configuration, const std::string& uid) {
  for (const auto& [wing, componentSegment] : everyComponentSegment(configuration)) {
    if (!componentSegment->structure) continue;
    const schema::WingComponentSegmentStructureType& structure = *componentSegment->structure;
    for (const bool upper : {true, false}) {
      const auto& shell = upper ? structure.upperShell : structure.lowerShell;
      if (!shell || !shell->cells) continue;
      for (const auto& cell : shell->cells->cell)
        if (cell.uID == uid) return {cell.uID, cell.xpath, componentSegment->uID, wing->uID, upper, &cell, &structure};
    }
  }
  throw Error(ErrorCode::InvalidArgument, "no wing cell with uID '" + uid + "'");
}

}  // namespace airshape::structure
