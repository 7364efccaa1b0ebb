#include "tank_services.h"

#include "airshape/configuration.h"
#include "vessel.h"

namespace airshape::tank {

namespace {

class VesselServices final : public TankServices {
 public:
  Eigen::Affine3d vesselPlacement(const Configuration& configuration, const std::string& vesselUid) const override {
    return vesselNamed(configuration, vesselUid)->placement;
  }

  std::shared_ptr<const schema::FuselageType> vesselBody(const Configuration& configuration,
                                                         const std::string& vesselUid) const override {
    return vesselNamed(configuration, vesselUid)->body;
  }

  std::shared_ptr<const schema::FuselageStructureType> vesselStructure(const Configuration& configuration,
                                                                       const std::string& vesselUid) const override {
    return vesselNamed(configuration, vesselUid)->structure;
  }
};

}  // namespace

std::shared_ptr<const TankServices> makeTankServices() { return std::make_shared<VesselServices>(); }

}  // namespace airshape::tank
