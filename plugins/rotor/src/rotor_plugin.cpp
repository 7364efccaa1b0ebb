// The rotor plugin: rotors of rotorcraft models with their hubs and attached blades. The blades
// themselves are wings, built by the wing plugin; this plugin places copies of them through the
// wing plugin's public interface (airshape/wing/wing_services.h) and answers the rotor ops.
#include <cmath>

#include "airshape/configuration.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/query/arguments.h"
#include "airshape/wing/wing_services.h"
#include "rotor_geometry.h"
#include "rotor_list.h"

namespace airshape::rotor {
namespace {

using query::Json;
using Services = std::shared_ptr<const wing::WingServices>;

/// The rotor a query names by its 1-based index among the addressed rotors or by uID.
const schema::RotorType& selectRotor(const Configuration& configuration, const Json& query) {
  const std::vector<const schema::RotorType*> rotors = addressedRotors(configuration);
  std::vector<std::string> uids;
  for (const schema::RotorType* rotor : rotors) uids.push_back(rotor->uID);
  return *rotors[query::selectByIndexOrUid(query, "rotor", uids, "rotor")];
}

/// Rotors (their hubs with the blades attached).
std::vector<plugin::NodeType> declaredNodeTypes() {
  return {plugin::NodeType{"rotor", "rotors/rotor"}.inBox().placedByItsTransformation()};
}

class RotorPlugin final : public plugin::BasicPlugin {
 public:
  RotorPlugin()
      : BasicPlugin("rotor", "0.2.0", "rotors with their hubs and attached blades", declaredNodeTypes(),
                    {{"wing", "0.1.0", "1.0.0"}}) {}

  void useServices(const plugin::ServiceRegistry& services) override {
    wing_ = services.find<wing::WingServices>(wing::kWingServices);
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    const Services wing = wing_;
    shapes.add("rotor", [wing](const Configuration& c, const std::string& uid) {
      return RotorGeometry(c, *wing, *rotorNamed(c, uid).rotor).shape();
    });
  }

  void registerQueries(query::QueryRegistry& registry) const override {
    const Services wing = wing_;
    // An op on one rotor's geometry.
    auto measure = [&registry, wing](const char* name, const char* help, auto figure) {
      registry.add({name, "", help, [wing, figure](Configuration& c, const Json& q) -> Json {
                      return figure(RotorGeometry(c, *wing, selectRotor(c, q)));
                    }});
    };
    registry.add({"rotor_count", "", "-> number of rotors of the model",
                  [](Configuration& c, const Json&) -> Json { return addressedRotors(c).size(); }});
    registry.add({"rotor_uid", "", "rotor -> uID",
                  [](Configuration& c, const Json& q) -> Json { return selectRotor(c, q).uID; }});
    measure("rotor_blade_count", "rotor -> number of attached blades",
            [](const RotorGeometry& r) -> Json { return r.bladeCount(); });
    measure("rotor_radius", "rotor -> radius", [](const RotorGeometry& r) -> Json { return r.radius(); });
    measure("rotor_reference_area", "rotor -> pi radius^2",
            [](const RotorGeometry& r) -> Json { return M_PI * std::pow(r.radius(), 2); });
    measure("rotor_total_blade_planform_area", "rotor -> planform area of all blades",
            [](const RotorGeometry& r) -> Json { return r.totalBladePlanformArea(); });
    measure("rotor_solidity", "rotor -> blade planform area / reference area", [](const RotorGeometry& r) -> Json {
      return r.totalBladePlanformArea() / (M_PI * std::pow(r.radius(), 2));
    });
    measure("rotor_tip_speed", "rotor -> tip speed in m/s",
            [](const RotorGeometry& r) -> Json { return r.tipSpeed(); });
    registry.add(
        {"rotor_volume", "", "rotor -> volume of all attached blades", [](Configuration& c, const Json& q) -> Json {
           return geometry::enclosedVolume(c.shapes().shapeOf(c, selectRotor(c, q).uID));
         }});
    registry.add(
        {"rotor_surface_area", "", "rotor -> area of all attached blades", [](Configuration& c, const Json& q) -> Json {
           return geometry::areaOf(c.shapes().shapeOf(c, selectRotor(c, q).uID));
         }});
  }

 private:
  Services wing_;
};

}  // namespace
}  // namespace airshape::rotor

AIRSHAPE_PLUGIN(airshape::rotor::RotorPlugin)
