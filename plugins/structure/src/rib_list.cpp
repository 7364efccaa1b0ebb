#include "rib_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "component_segments.h"

namespace airshape::structure {

RibsDefinition ribsDefinitionNamed(const Configuration& configuration, const std::string& uid) {
  for (const auto& [wing, componentSegment] : everyComponentSegment(configuration)) {
    if (!componentSegment->structure || !componentSegment->structure->ribsDefinitions) continue;
    for (const auto& ribs : componentSegment->structure->ribsDefinitions->ribsDefinition)
      if (ribs.uID == uid)
        return {ribs.uID, ribs.xpath, componentSegment->uID, wing->uID, &ribs, &*componentSegment->structure};
  }
  throw Error(ErrorCode::InvalidArgument, "no ribs definition with uID '" + uid + "'");
}

}  // namespace airshape::structure
