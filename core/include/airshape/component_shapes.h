#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <gp_Trsf.hxx>

#include "airshape/error.h"
#include "airshape/named_shape.h"

namespace airshape {

class Configuration;

/// Builds the solid of one component (by uID) of a configuration, its faces named.
using ShapeBuilder = std::function<NamedShape(const Configuration& configuration, const std::string& uid)>;

/// How a component moves inside the component it was cut from, by one control parameter (a
/// device in the surface it was cut from), as the plugin that builds it says; the core poses such components for
/// exports without knowing what they are.
struct ComponentMotion {
  /// The control parameters of its first and its last position.
  std::function<std::pair<double, double>(const Configuration& configuration, const std::string& uid)> range;
  /// Its rigid motion at a control parameter; Error outside the range.
  std::function<gp_Trsf(const Configuration& configuration, const std::string& uid, double parameter)> at;
  /// What its host (the exported component it lies in) loses when it moves: a solid to cut
  /// out of the host, or a compound of solids that may overlap, its faces named.
  std::function<NamedShape(const Configuration& configuration, const std::string& uid)> cutOut;
};

/// Solids that some components cut out of others while a build option is on (the cut-outs
/// that passages through other components make, as the plugin that builds the passages declares
/// them). Options are off by default; Configuration::setOption turns one on.
struct ComponentCutOuts {
  std::string option;       ///< the option's name, e.g. "duct_cutouts"
  std::string description;  ///< one line for help texts
  /// The solids to cut out of the component with this uID (none when nothing cuts it).
  std::function<std::vector<NamedShape>(const Configuration& configuration, const std::string& uid)> tools;
};

/// The shape builders plugins register, by CPACS node type, so that any code (a component asking
/// for its parent's solid, the bounding box, exports) gets a component's solid without
/// knowing which plugin builds it.
class ComponentShapes {
 public:
  void add(const std::string& nodeType, ShapeBuilder builder) { builders_[nodeType] = std::move(builder); }
  /// The builder of a node type, or nullptr.
  const ShapeBuilder* find(const std::string& nodeType) const {
    const auto entry = builders_.find(nodeType);
    return entry == builders_.end() ? nullptr : &entry->second;
  }

  /// A node type its plugin knowingly leaves unbuilt, and why (one line: "the schema gives ...").
  /// `build` and `info` say it for each such element; asking for its shape is an Error saying it.
  void decline(const std::string& nodeType, std::string reason) { declined_[nodeType] = std::move(reason); }
  /// Why a node type is left unbuilt, or nullptr when it is not declined.
  const std::string* declined(const std::string& nodeType) const {
    const auto entry = declined_.find(nodeType);
    return entry == declined_.end() ? nullptr : &entry->second;
  }

  /// A detailed shape for components whose shape is a simplification: stiffeners
  /// are lines, and their detailed shape the profile swept along the line. Exports ask for it
  /// (ExportOptions::profiles); queries always measure the shape `add` builds.
  void addDetailed(const std::string& nodeType, ShapeBuilder builder) {
    detailedBuilders_[nodeType] = std::move(builder);
  }
  /// The detailed builder of a node type, or nullptr.
  const ShapeBuilder* findDetailed(const std::string& nodeType) const {
    const auto entry = detailedBuilders_.find(nodeType);
    return entry == detailedBuilders_.end() ? nullptr : &entry->second;
  }

  void addMotion(const std::string& nodeType, ComponentMotion motion) { motions_[nodeType] = std::move(motion); }
  /// How components of a node type move, or nullptr for those that do not.
  const ComponentMotion* findMotion(const std::string& nodeType) const {
    const auto entry = motions_.find(nodeType);
    return entry == motions_.end() ? nullptr : &entry->second;
  }

  void addCutOuts(ComponentCutOuts cutOuts) { cutOuts_.push_back(std::move(cutOuts)); }
  /// Every declared kind of cut-out, with its option.
  const std::vector<ComponentCutOuts>& cutOuts() const { return cutOuts_; }

  /// The solid of the component with this uID and its face names, built once and cached
  /// in the configuration, with what others cut out of it while their option is on. Throws
  /// Error when no component has the uID or no plugin builds its type.
  const NamedShape& namedShapeOf(const Configuration& configuration, const std::string& uid) const;
  /// The solid as its plugin builds it, whatever cut-outs are on: what lies inside a component
  /// (its devices, its structure) is made from this one.
  const NamedShape& cleanNamedShapeOf(const Configuration& configuration, const std::string& uid) const;
  /// Whether namedShapeOf gives the component with cut-outs taken out of it (false at once,
  /// building nothing, while no cut-out option is on).
  bool isCutByOthers(const Configuration& configuration, const std::string& uid) const;
  /// The mirrored half of a component with a symmetry plane (CPACS `symmetry`, inherited
  /// through parentUID): its solid mirrored, faces named as the original's plus
  /// " (mirrored)". Throws Error when the component has no symmetry.
  const NamedShape& mirroredShapeOf(const Configuration& configuration, const std::string& uid) const;
  /// The solid alone.
  const TopoDS_Shape& shapeOf(const Configuration& configuration, const std::string& uid) const {
    return namedShapeOf(configuration, uid).shape;
  }

 private:
  std::map<std::string, ShapeBuilder> builders_;
  std::map<std::string, ShapeBuilder> detailedBuilders_;
  std::map<std::string, ComponentMotion> motions_;
  std::map<std::string, std::string> declined_;
  std::vector<ComponentCutOuts> cutOuts_;

  /// Whether any declared cut-out option is on in the configuration.
  bool anyCutOutsOn(const Configuration& configuration) const;
};

/// Why a component of this node type has no shape to give: the model (the plane itself) has
/// none; a type its plugin declines says why; a type no loaded plugin builds says so. The Error
/// to throw where a shape is asked for.
Error noShapeBuilt(const std::string& uid, const std::string& nodeType, const std::string* declinedBecause = nullptr);

}  // namespace airshape
