#pragma once

#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::tank {

/// What the tank plugin offers the plugins that build inside tanks (the structure plugin's
/// walls in a vessel): where a vessel lies and what it holds. Offered as the service named
/// kTankServices; a plugin that uses it requires the tank plugin (docs/plugins.md). Errors are
/// airshape::Error naming the node.
class TankServices {
 public:
  virtual ~TankServices() = default;

  /// The matrix that takes a vessel's own frame (where its walls are positioned) to the
  /// global one: its tank's placement, then its own transformation.
  virtual Eigen::Affine3d vesselPlacement(const Configuration& configuration, const std::string& vesselUid) const = 0;

  /// The vessel's sections and segments, read into the 3.5 fuselage type (null for a vessel of
  /// design parameters).
  virtual std::shared_ptr<const schema::FuselageType> vesselBody(const Configuration& configuration,
                                                                 const std::string& vesselUid) const = 0;

  /// The vessel's structure (walls, frames), read into the 3.5 type of a fuselage's (null
  /// when it has none).
  virtual std::shared_ptr<const schema::FuselageStructureType> vesselStructure(const Configuration& configuration,
                                                                               const std::string& vesselUid) const = 0;
};

/// The service name; the number changes whenever TankServices does.
inline constexpr const char* kTankServices = "airshape.tank.TankServices/1";

}  // namespace airshape::tank
