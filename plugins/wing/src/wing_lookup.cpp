#include "wing_lookup.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/wing/wing_list.h"

namespace airshape::wing {

const schema::WingType& wingHolding(const Configuration& configuration, const std::string& partUid) {
  const graph::ComponentGraph& graph = configuration.components();
  const long part = graph.find(partUid);
  if (part < 0) throw Error(ErrorCode::InvalidArgument, "no component with uID '" + partUid + "'");
  const std::string& wingUid = graph.components()[static_cast<std::size_t>(part)].parentUid;
  return wingNamed(configuration, wingUid);
}

const schema::ComponentSegmentType& componentSegmentNamed(const schema::WingType& wing, const std::string& uid) {
  if (wing.componentSegments)
    for (const auto& candidate : wing.componentSegments->componentSegment)
      if (candidate.uID == uid) return candidate;
  throw Error(ErrorCode::InvalidArgument, "wing '" + wing.uID + "' has no component segment '" + uid + "'");
}

}  // namespace airshape::wing
