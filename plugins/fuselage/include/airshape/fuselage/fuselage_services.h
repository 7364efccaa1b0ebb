#pragma once

#include <string>

#include <Eigen/Geometry>

#include "airshape/named_shape.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::fuselage {

/// What the fuselage plugin offers the plugins that build on fuselages (tanks, a third
/// party's): bodies lofted as fuselages are, from sections of fuselage profiles, segments and
/// guide curves, wherever they are defined. It is offered as the service named
/// kFuselageServices; a plugin that uses it requires the fuselage plugin and takes it in
/// Plugin::useServices (docs/plugins.md). Errors are airshape::Error naming the node.
class FuselageServices {
 public:
  virtual ~FuselageServices() = default;

  /// The solid of a body defined as a fuselage is (its uID unique in the document), its
  /// profiles placed by `placement` (the matrix that takes the body's own frame to the global
  /// one) instead of a component transformation of its own. Faces are named as a fuselage's.
  virtual NamedShape bodySolid(const Configuration& configuration, const schema::FuselageType& body,
                               const Eigen::Affine3d& placement) const = 0;

  /// The solid of one of that body's segments, by uID.
  virtual NamedShape bodySegmentSolid(const Configuration& configuration, const schema::FuselageType& body,
                                      const Eigen::Affine3d& placement, const std::string& segmentUid) const = 0;
};

/// The service name; the number changes whenever FuselageServices does.
inline constexpr const char* kFuselageServices = "airshape.fuselage.FuselageServices/1";

}  // namespace airshape::fuselage
