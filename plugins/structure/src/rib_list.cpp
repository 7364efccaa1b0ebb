#include "rib_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/primary_model.h"

namespace airshape::structure {

RibsDefinition ribsDefinitionNamed(const Configuration& configuration, const std::string& uid) {
  for (const model::ModelComponents& model : model::everyModel(configuration))
    for (const schema::WingType* wing : model.wings) {
      if (!wing->componentSegments) continue;
      for (const auto& componentSegment : wing->componentSegments->componentSegment) {
        if (!componentSegment.structure || !componentSegment.structure->ribsDefinitions) continue;
        for (const auto& ribs : componentSegment.structure->ribsDefinitions->ribsDefinition)
          if (ribs.uID == uid)
            return {ribs.uID, ribs.xpath, componentSegment.uID, wing->uID, &ribs, &*componentSegment.structure};
      }
    }
  throw Error(ErrorCode::InvalidArgument, "no ribs definition with uID '" + uid + "'");
}

}  // namespace airshape::structure
