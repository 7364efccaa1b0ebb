#include "cell_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "component_segments.h"

namespace airshape::structure {

WingCell wingCellNamed(const Configuration& configuration, const std::string& uid) {
  for (const StructureHost& host : everyStructure(configuration)) {
    const schema::WingComponentSegmentStructureType& structure = *host.structure;
    for (const bool upper : {true, false}) {
      const auto& shell = upper ? structure.upperShell : structure.lowerShell;
      if (!shell || !shell->cells) continue;
      for (const auto& cell : shell->cells->cell)
        if (cell.uID == uid)
          return {cell.uID,   cell.xpath,    host.componentSegment->uID, host.wing->uID, upper, &cell,
                  &structure, host.deviceUid};
    }
  }
  throw Error(ErrorCode::InvalidArgument, "no wing cell with uID '" + uid + "'");
}

}  // namespace airshape::structure
