#include "cell_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/primary_model.h"

namespace airshape::structure {

WingCell wingCellNamed(const Configuration& configuration, const std::string& uid) {
  for (const model::ModelComponents& model : model::everyModel(configuration))
    for (const schema::WingType* wing : model.wings) {
      if (!wing->componentSegments) continue;
      for (const auto& componentSegment : wing->componentSegments->componentSegment) {
        if (!componentSegment.structure) continue;
        const schema::WingComponentSegmentStructureType& structure = *componentSegment.structure;
        for (const bool upper : {true, false}) {
          const auto& shell = upper ? structure.upperShell : structure.lowerShell;
          if (!shell || !shell->cells) continue;
          for (const auto& cell : shell->cells->cell)
            if (cell.uID == uid)
              return {cell.uID, cell.xpath, componentSegment.uID, wing->uID, upper, &cell, &structure};
        }
      }
    }
  throw Error(ErrorCode::InvalidArgument, "no wing cell with uID '" + uid + "'");
}

}  // namespace airshape::structure
