#include "vessel.h"

#include <cmath>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/schema/element_reading.h"
#include "airshape/xml/text.h"
#include "dome_meridian.h"
#include "vessel_of_revolution.h"

namespace airshape::tank {

namespace {

using xercesc::DOMElement;

/// The own transformation of an element (identity without one).
model::Transform ownTransformation(const DOMElement& element, const std::string& xpath) {
  const auto transformation = schema::readChild<schema::TransformationType>(element, "transformation", xpath);
  return model::transformationMatrix(transformation.get());
}

/// A tank's placement: its own transformation (a model tank's), translated by the origin of
/// the component it is attached to (its parentUID, else the fuselage it lies in) unless its
/// translation is absGlobal.
model::Transform tankPlacement(const Configuration& configuration, const graph::Component& tank) {
  const auto transformation =
      schema::readChild<schema::TransformationType>(*tank.element, "transformation", tank.xpath);
  return model::placedOnParent(configuration, transformation.get(), tank.parentUid);
}

std::shared_ptr<const Vessel> readVessel(const Configuration& configuration, const graph::Component& component) {
  auto vessel = std::make_shared<Vessel>();
  vessel->uid = component.uid;
  const DOMElement* element = component.element;
  const graph::Component* tank = &component;
  if (component.nodeType == "fuelTank") {  // a CPACS 3.5 tank of design parameters
    element = xml::firstChild(*component.element, "designParameters");
    if (element == nullptr)
      throw Error(ErrorCode::InvalidModel, "the tank has neither hulls nor design parameters", {}, component.xpath);
    vessel->xpath = component.xpath + "/designParameters";
  } else {
    tank = &configuration.components().named(component.parentUid);
    vessel->xpath = component.xpath;
  }
  vessel->placement = tankPlacement(configuration, *tank) * ownTransformation(*element, vessel->xpath);
  // Vessels of model tanks are newer than the CPACS 3.5 schema: read here into the 3.5 types
  // they share.
  if (xml::firstChild(*element, "sections") != nullptr)
    vessel->body = schema::readElement<schema::FuselageType>(*element, vessel->xpath);
  vessel->cylinderRadius = schema::numberIn(*element, "cylinderRadius", vessel->xpath);
  vessel->cylinderLength = schema::numberIn(*element, "cylinderLength", vessel->xpath);
  vessel->dome = schema::readChild<schema::DomeTypeType>(*element, "domeType", vessel->xpath);
  vessel->structure = schema::readChild<schema::FuselageStructureType>(*element, "structure", vessel->xpath);
  return vessel;
}

/// The front dome a vessel's design parameters give.
DomeMeridian domeOf(const Vessel& vessel) {
  const schema::DomeTypeType& dome = *vessel.dome;
  const double radius = *vessel.cylinderRadius;
  if (dome.ellipsoid) return ellipsoidDome(radius, dome.ellipsoid->halfAxisFraction);
  if (dome.torispherical)
    return torisphericalDome(radius, dome.torispherical->dishRadius, dome.torispherical->knuckleRadius);
  if (dome.isotensoid) return isotensoidDome(radius, dome.isotensoid->polarOpeningRadius);
  if (dome.spherical) return ellipsoidDome(radius, 1.0);
  throw Error(ErrorCode::InvalidModel, "the dome type names no dome (spherical, ellipsoid, torispherical, isotensoid)");
}

NamedShape revolvedVessel(const Vessel& vessel) {
  if (!vessel.dome || !vessel.cylinderRadius || !vessel.cylinderLength)
    throw Error(ErrorCode::InvalidModel,
                "the vessel needs sections and segments, or cylinderRadius, cylinderLength and domeType", {},
                vessel.xpath);
  if (*vessel.cylinderRadius <= 0.0)
    throw Error(ErrorCode::InvalidModel, "the cylinder radius must be positive", {}, vessel.xpath + "/cylinderRadius");
  if (*vessel.cylinderLength < 0.0)
    throw Error(ErrorCode::InvalidModel, "the cylinder length must not be negative", {},
                vessel.xpath + "/cylinderLength");
  try {
    const NamedShape own =
        vesselOfRevolution(domeOf(vessel), *vessel.cylinderRadius, *vessel.cylinderLength, vessel.uid);
    return transformedNamedShape(own, vessel.placement);
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), error.message(), {}, vessel.xpath + "/domeType");
  }
}

}  // namespace

std::shared_ptr<const Vessel> vesselNamed(const Configuration& configuration, const std::string& uid) {
  return configuration.cache().obtain<Vessel>(
      "vessel:" + uid, [&] { return readVessel(configuration, configuration.components().named(uid)); });
}

std::vector<std::string> vesselsOfTank(const Configuration& configuration, const std::string& tankUid) {
  std::vector<std::string> vessels;
  for (const graph::Component& component : configuration.components().components())
    if (component.nodeType == "tankHull" && component.parentUid == tankUid) vessels.push_back(component.uid);
  if (vessels.empty() && xml::firstChild(*configuration.components().named(tankUid).element, "designParameters"))
    vessels.push_back(tankUid);
  return vessels;
}

NamedShape vesselSolid(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                       const Vessel& vessel) {
  if (vessel.body) return fuselages.bodySolid(configuration, *vessel.body, vessel.placement);
  return revolvedVessel(vessel);
}

}  // namespace airshape::tank
