#include "fuselage_services.h"

#include <algorithm>

#include "airshape/error.h"
#include "fuselage_geometry.h"

namespace airshape::fuselage {

namespace {

class FuselageServicesOfThisPlugin final : public FuselageServices {
 public:
  NamedShape bodySolid(const Configuration& configuration, const schema::FuselageType& body,
                       const Eigen::Affine3d& placement) const override {
    return FuselageGeometry::of(configuration, body, placement)->solid(body.uID);
  }

  NamedShape bodySegmentSolid(const Configuration& configuration, const schema::FuselageType& body,
                              const Eigen::Affine3d& placement, const std::string& segmentUid) const override {
    const auto geometry = FuselageGeometry::of(configuration, body, placement);
    const auto& uids = geometry->segmentUids();
    const auto found = std::find(uids.begin(), uids.end(), segmentUid);
    if (found == uids.end())
      throw Error(ErrorCode::InvalidArgument, "no segment with uID '" + segmentUid + "'", {}, body.xpath);
    return geometry->segmentSolid(static_cast<std::size_t>(found - uids.begin()));
  }
};

}  // namespace

std::shared_ptr<const FuselageServices> makeFuselageServices() {
  return std::make_shared<FuselageServicesOfThisPlugin>();
}

}  // namespace airshape::fuselage
