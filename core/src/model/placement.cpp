#include "airshape/model/placement.h"

#include <cmath>
#include <functional>
#include <optional>
#include <sstream>

#include <Eigen/Geometry>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/schema/node_lookup.h"

namespace airshape::model {

namespace {

double degrees(double value) { return value * M_PI / 180.0; }

/// The largest translation, scaling or angle a transformation may hold. Beyond it neighbouring
/// doubles lie more than OCCT's confusion distance (1e-7) apart, so that no shape placed there
/// can be built or checked (OCCT's shape check crashed on a body moved by 1e300).
constexpr double kLargestPlacement = 1e9;

/// One coordinate of a point type of a transformation, `absent` where it is left out.
double coordinate(const std::optional<double>& value, const std::string& xpath, double absent = 0.0) {
  if (!value) return absent;
  if (std::abs(finite(*value, xpath)) > kLargestPlacement) {
    std::ostringstream text;
    text << *value << " is beyond " << kLargestPlacement << ": no shape can be placed that far to OCCT's precision";
    throw Error(ErrorCode::InvalidModel, text.str(), {}, xpath);
  }
  return *value;
}

/// The own transformation and the parent of a component placed by its transformation.
struct Placed {
  const schema::TransformationType* transformation = nullptr;
  std::string parentUid;
};

/// The component with this uID if its plugin declares it placed by its own transformation.
std::optional<Placed> placedComponent(const Configuration& configuration, const std::string& uid) {
  const long index = configuration.components().find(uid);
  if (index < 0) return std::nullopt;
  const graph::Component& component = configuration.components().components()[static_cast<std::size_t>(index)];
  if (!component.placedByTransformation) return std::nullopt;
  schema::Node* node = schema::nodeBoundTo(configuration.cpacs(), *component.element);
  if (node == nullptr) return std::nullopt;
  return Placed{dynamic_cast<const schema::TransformationType*>(schema::childNode(*node, "transformation")),
                component.parentUid};
}

}  // namespace

gp_Pnt apply(const Transform& transform, const gp_Pnt& point) {
  const Eigen::Vector3d moved = transform * Eigen::Vector3d(point.X(), point.Y(), point.Z());
  return {moved.x(), moved.y(), moved.z()};
}

Transform transformationMatrix(const schema::TransformationType* transformation) {
  Transform result = Transform::Identity();
  if (transformation == nullptr) return result;
  if (const auto& t = transformation->translation)
    result.translate(Eigen::Vector3d(coordinate(t->x, t->xpath + "/x"), coordinate(t->y, t->xpath + "/y"),
                                     coordinate(t->z, t->xpath + "/z")));
  if (const auto& r = transformation->rotation) {
    result.rotate(Eigen::AngleAxisd(degrees(coordinate(r->x, r->xpath + "/x")), Eigen::Vector3d::UnitX()));
    result.rotate(Eigen::AngleAxisd(degrees(coordinate(r->y, r->xpath + "/y")), Eigen::Vector3d::UnitY()));
    result.rotate(Eigen::AngleAxisd(degrees(coordinate(r->z, r->xpath + "/z")), Eigen::Vector3d::UnitZ()));
  }
  // The schema's default scaling is 1, 1, 1; a coordinate left out keeps its 1.
  if (const auto& s = transformation->scaling)
    result.scale(Eigen::Vector3d(coordinate(s->x, s->xpath + "/x", 1.0), coordinate(s->y, s->xpath + "/y", 1.0),
                                 coordinate(s->z, s->xpath + "/z", 1.0)));
  return result;
}

Transform componentTransform(const Configuration& configuration, const std::string& uid) {
  Transform result = Transform::Identity();
  std::string current = uid;
  bool first = true;
  // Walks up the parent chain: the component's own matrix, then its parents' translations.
  for (std::size_t depth = 0; !current.empty() && depth < 64; ++depth) {
    const std::optional<Placed> placed = placedComponent(configuration, current);
    if (!placed) break;
    const Transform own = transformationMatrix(placed->transformation);
    if (first) {
      result = own;
      first = false;
    } else {
      result.pretranslate(own.translation());
    }
    const bool absGlobal = placed->transformation && placed->transformation->translation &&
                           placed->transformation->translation->refType == schema::PointAbsRelTypeRefType::AbsGlobal;
    if (absGlobal) break;
    current = placed->parentUid;
  }
  return result;
}

Transform placedOnParent(const Configuration& configuration, const schema::TransformationType* transformation,
                         const std::string& parentUid) {
  Transform placement = transformationMatrix(transformation);
  const bool absGlobal = transformation && transformation->translation &&
                         transformation->translation->refType == schema::PointAbsRelTypeRefType::AbsGlobal;
  if (!absGlobal && !parentUid.empty())
    placement.pretranslate(componentTransform(configuration, parentUid).translation());
  return placement;
}

std::unordered_map<std::string, Eigen::Vector3d> positioningTranslations(const schema::PositioningsType* positionings) {
  std::unordered_map<std::string, Eigen::Vector3d> result;
  if (positionings == nullptr) return result;
  std::unordered_map<std::string, const schema::PositioningType*> byTarget;  // the first one wins
  for (const auto& positioning : positionings->positioning) byTarget.emplace(positioning.toSectionUID, &positioning);

  std::unordered_map<std::string, int> visiting;
  std::function<Eigen::Vector3d(const std::string&)> toPoint = [&](const std::string& section) -> Eigen::Vector3d {
    if (const auto done = result.find(section); done != result.end()) return done->second;
    const auto entry = byTarget.find(section);
    if (entry == byTarget.end())
      throw Error(ErrorCode::InvalidModel, "fromSectionUID '" + section + "' names a section no positioning reaches");
    if (visiting[section]++ > 0)
      throw Error(ErrorCode::InvalidModel, "positionings loop through section '" + section + "'", {},
                  entry->second->xpath);
    const schema::PositioningType& p = *entry->second;
    const std::string from = p.fromSectionUID.value_or("");
    const Eigen::Vector3d origin = from.empty() ? Eigen::Vector3d::Zero() : toPoint(from);
    const double sweep = degrees(finite(p.sweepAngle, p.xpath + "/sweepAngle")),
                 dihedral = degrees(finite(p.dihedralAngle, p.xpath + "/dihedralAngle"));
    const Eigen::Vector3d step =
        finite(p.length, p.xpath + "/length") *
        Eigen::Vector3d(std::sin(sweep), std::cos(sweep) * std::cos(dihedral), std::cos(sweep) * std::sin(dihedral));
    return result[section] = origin + step;
  };
  for (const auto& [section, positioning] : byTarget) {
    try {
      toPoint(section);
    } catch (const Error& error) {
      if (!error.cpacsPath().empty()) throw;
      throw Error(error.code(), error.message(), {}, positioning->xpath);
    }
  }
  return result;
}

double finite(double value, const std::string& xpath) {
  if (!std::isfinite(value)) throw Error(ErrorCode::InvalidModel, "not a finite number (NaN or INF)", {}, xpath);
  return value;
}

double fraction(double value, const std::string& xpath) {
  if (!(value >= 0.0 && value <= 1.0)) {
    std::ostringstream text;
    text << value << " is not a number in [0, 1]";
    throw Error(ErrorCode::InvalidModel, text.str(), {}, xpath);
  }
  return value;
}

std::vector<double> parseVector(const std::string& text, const std::string& xpath) {
  std::vector<double> values;
  if (schema::ParseError error = schema::DoubleVectorCodec::parse(text, values))
    throw Error(ErrorCode::InvalidModel, *error, {}, xpath);
  for (double value : values) finite(value, xpath);
  return values;
}

}  // namespace airshape::model
