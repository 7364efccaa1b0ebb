#pragma once

#include <cstddef>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace airshape::exporting {

/// How far an export has come, reported while components are built and files written.
struct ExportProgress {
  std::size_t componentsBuilt = 0;
  std::size_t componentsTotal = 0;
  double seconds = 0;  ///< since the export started
  std::string step;    ///< what is being done now, e.g. "built W1", "meshing", "writing STEP"
};

/// The control parameter at which an export shows a moving component (a control
/// device): `airshape export --deflect UID=P`.
struct Pose {
  enum class At { Parameter, Minimum, Maximum };
  std::string uid;  ///< a moving component's uID, or "all" for every one
  At at = At::Parameter;
  double parameter = 0.0;  ///< with At::Parameter
};

/// What an export writes and how finely it triangulates.
struct ExportOptions {
  /// uIDs of the components to write; empty: every component a plugin builds.
  std::vector<std::string> components;
  /// Also write the mirrored halves of components with a symmetry plane.
  bool mirror = false;
  /// Write one solid: the Boolean union of all components (and halves, with `mirror`).
  bool fused = false;
  /// Moving components to show posed: each is written as a solid of its own at its control
  /// parameter, and the component it lies in (its host) with the cut-outs of those posed in
  /// it, in one Boolean operation. Empty: every component as built, at rest.
  std::vector<Pose> poses;
  /// Write the structural model instead of the components: for each component with structure
  /// inside (a host's parts with the structure declared inside them), one connected shell of
  /// its faces split where the structure meets them and the structure's faces, sharing their
  /// edges (a FEM mesher meshes it conformally). `components` then names the hosts (or their
  /// parents) whose structure to write.
  bool structure = false;
  /// Write components that have a detailed shape (ComponentShapes::addDetailed: stiffeners
  /// with their profiles swept along their lines) with it instead of their shape;
  /// where the detailed shape cannot be built, the shape is written and ExportScene::notes
  /// says why.
  bool profiles = false;
  /// Leave out components that fail to build (ExportScene::leftOut says which and why)
  /// instead of failing the export.
  bool skipFailed = false;
  /// Largest distance (model units, metres) between a triangle and the surface for the
  /// triangulated formats; 0 chooses it per component as 1 % of its volume / area
  /// ratio (a measure of its thickness), which keeps the enclosed volume within a few
  /// tenths of a percent for thin and round bodies alike.
  double linearDeflection = 0;
  /// Largest angle (radians) between the normals along a triangle edge.
  double angularDeflection = 0.2;
  /// Called as work goes on; may be empty.
  std::function<void(const ExportProgress&)> progress;
};

/// The items of a comma-separated list ("W1,W2" for `components`), empty ones dropped.
inline std::vector<std::string> splitAtCommas(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream stream(list);
  for (std::string item; std::getline(stream, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

/// A command-line value that must be a positive number, the whole text (`option` names it in
/// the Error(InvalidArgument) thrown otherwise).
double positiveNumber(const std::string& text, const std::string& option);

/// Poses written as "UID=P,UID=P,..." where P is a number, "min" or "max" and UID may be
/// "all" (then P is min or max). Throws Error(InvalidArgument) on anything else.
std::vector<Pose> parsePoses(const std::string& list);

}  // namespace airshape::exporting
