// The tank plugin: fuel tanks and their vessels (hulls), lofted from sections and segments
// by the fuselage plugin's public interface (airshape/fuselage/fuselage_services.h) or
// revolved from design parameters (a cylinder between two domes). It reads the tanks of the
// model's own fuelTanks (the layout after CPACS 3.5 that the reference reads) and the CPACS
// 3.5 tanks inside fuselages (genericFuelTanks with hulls or design parameters).
#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/xml/text.h"
#include "tank_services.h"
#include "vessel.h"

namespace airshape::tank {
namespace {

/// A tank: the compound of its vessels' solids (an outer and an inner vessel overlap), or the
/// one solid of its design parameters.
NamedShape tankShape(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                     const std::string& uid) {
  const graph::Component& tank = configuration.components().named(uid);
  if (xml::name(*tank.element) == "integralFuelTank")
    throw Error(ErrorCode::NotImplemented, "integral fuel tanks (bounded by fuselage structure) are not built yet", {},
                tank.xpath);
  const std::vector<std::string> vessels = vesselsOfTank(configuration, uid);
  if (vessels.empty()) throw NoShape("the tank has no vessels: no shape", tank.xpath);
  if (vessels == std::vector{uid}) return vesselSolid(configuration, fuselages, *vesselNamed(configuration, uid));
  std::vector<const NamedShape*> solids;
  for (const std::string& vesselUid : vessels)
    solids.push_back(&configuration.shapes().namedShapeOf(configuration, vesselUid));
  return compoundOfNamedShapes(solids);
}

/// Tanks with their vessels and the vessels' segments (parts of the vessel's solid): the model's
/// own tanks (model/fuelTanks/fuelTank/vessels/vessel, newer than CPACS 3.5's schema; real files
/// and the reference use it) and CPACS 3.5's tanks in fuselages, which the reference does not
/// read: built, but not listed.
std::vector<plugin::NodeType> declaredNodeTypes() {
  using plugin::NodeType;
  return {
      NodeType{"fuelTank", "fuelTanks/fuelTank"}.typed("tank"),
      NodeType{"fuelTank", "fuelTanks/genericFuelTanks/genericFuelTank"}.inside("fuselage").typed("tank").unlisted(),
      NodeType{"fuelTank", "fuelTanks/integralFuelTanks/integralFuelTank"}.inside("fuselage").typed("tank").unlisted(),
      NodeType{"tankHull", "vessels/vessel"}.inside("fuelTank").typed("tank_hull"),
      NodeType{"tankHull", "hulls/hull"}.inside("fuelTank").typed("tank_hull"),
      NodeType{"hullSegment", "segments/segment"}.inside("tankHull").typed("fuselage_segment").asPart()};
}

class TankPlugin final : public plugin::BasicPlugin {
 public:
  TankPlugin()
      : BasicPlugin("tank", "0.2.0", "fuel tanks and their vessels: lofted bodies or cylinders between domes",
                    declaredNodeTypes(), {{"fuselage", "0.3.0", "1.0.0"}}) {}

  void useServices(const plugin::ServiceRegistry& services) override {
    fuselages_ = services.find<fuselage::FuselageServices>(fuselage::kFuselageServices);
  }

  void offerServices(plugin::ServiceRegistry& services) const override {
    services.offer<TankServices>(kTankServices, makeTankServices());
  }

  void registerShapeBuilders(ComponentShapes& shapes) const override {
    const std::shared_ptr<const fuselage::FuselageServices> fuselages = fuselages_;
    shapes.add("fuelTank",
               [fuselages](const Configuration& c, const std::string& uid) { return tankShape(c, *fuselages, uid); });
    shapes.add("tankHull", [fuselages](const Configuration& c, const std::string& uid) {
      return vesselSolid(c, *fuselages, *vesselNamed(c, uid));
    });
    shapes.add("hullSegment", [fuselages](const Configuration& c, const std::string& uid) {
      const std::string& vesselUid = c.components().named(uid).parentUid;
      const auto vessel = vesselNamed(c, vesselUid);
      if (!vessel->body) throw Error(ErrorCode::InvalidModel, "the vessel has no segments", {}, vessel->xpath);
      return fuselages->bodySegmentSolid(c, *vessel->body, vessel->placement, uid);
    });
  }

 private:
  std::shared_ptr<const fuselage::FuselageServices> fuselages_;
};

}  // namespace
}  // namespace airshape::tank

AIRSHAPE_PLUGIN(airshape::tank::TankPlugin)
