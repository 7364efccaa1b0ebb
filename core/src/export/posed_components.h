#pragma once

#include <map>
#include <string>
#include <vector>

#include <gp_Trsf.hxx>

#include "airshape/export/export_options.h"
#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::exporting {

/// A moving component an export shows at a control parameter.
struct PosedComponent {
  std::string uid;
  double parameter = 0.0;
  /// Where it is written: its own rigid motion after that of every posed moving component it
  /// lies in (a tab moves with its device).
  gp_Trsf motion;
  /// The component that loses its cut-out: the nearest one it lies in that is posed too, or
  /// else the exported component it lies in (a device's host).
  std::string host;
  /// The components it lies in, nearest first (a tab's device, then its hosts outwards).
  std::vector<std::string> within;
  /// Whether the poses name it on its own (not only by `all`).
  bool named = false;
};

/// The components the poses name, each with its control parameter, motion and host, by uID.
/// Throws Error naming the uID when a pose names no moving component or a parameter outside
/// its range.
std::map<std::string, PosedComponent> resolvePoses(const Configuration& configuration, const std::vector<Pose>& poses);

/// The solid an export writes for a component when some are posed: as built, less the
/// cut-outs of the posed components it hosts (one Boolean cut, the cut faces named as the
/// moving components name them), moved by its own motion when it is posed itself. Throws
/// Error naming the component when the cut fails.
NamedShape posedSolid(const Configuration& configuration, const std::string& uid,
                      const std::map<std::string, PosedComponent>& posed);

}  // namespace airshape::exporting
