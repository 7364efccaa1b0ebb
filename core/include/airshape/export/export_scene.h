#pragma once

#include <string>
#include <vector>

#include "airshape/export/export_options.h"
#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::exporting {

/// One solid to write: a component, its mirrored half, or the fused aircraft.
struct SceneComponent {
  std::string name;  ///< the component's uID; "<uID> (mirrored)" for a mirrored half
  NamedShape shape;  ///< its own copy, so meshing it never touches the cached geometry
  std::string type;  ///< its component type (QUERY-components §1.1); empty for a union or a structural model
};

/// What an export writes, in build order: the selected components' solids (built in
/// parallel where the component graph allows), their mirrored halves on request, or
/// their union.
struct ExportScene {
  std::string name;  ///< the configuration's file name, the STEP assembly's name
  std::vector<SceneComponent> components;
  /// Components left out because they failed to build (with skipFailed): "uID: why".
  std::vector<std::string> leftOut;
  /// Components written otherwise than asked, "uID: what and why" (a stiffener written as its line
  /// because its profile cannot be swept).
  std::vector<std::string> notes;
};

/// Builds the scene of a configuration. Throws Error naming the component when a selected
/// uID names nothing, or when a component fails to build (unless skipFailed: then it is in
/// leftOut); components no plugin builds yet are left out unless selected by uID (then it is
/// an error). The scene is empty when no plugin builds any component.
ExportScene buildScene(const Configuration& configuration, const ExportOptions& options);

}  // namespace airshape::exporting
