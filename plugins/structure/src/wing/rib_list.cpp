#include "rib_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "component_segments.h"

namespace airshape::structure {

RibsDefinition ribsDefinitionNamed(const Configuration& configuration, const std::string& uid) {
  for (const StructureHost& host : everyStructure(configuration)) {
    if (!host.structure->ribsDefinitions) continue;
    for (const auto& ribs : host.structure->ribsDefinitions->ribsDefinition)
      if (ribs.uID == uid)
        return {ribs.uID,       ribs.xpath,    host.componentSegment->uID, host.wing->uID, &ribs,
                host.structure, host.deviceUid};
  }
  throw Error(ErrorCode::InvalidArgument, "no ribs definition with uID '" + uid + "'");
}

}  // namespace airshape::structure
