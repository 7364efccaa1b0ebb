#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <xercesc/dom/DOMElement.hpp>

#include "airshape/fuselage/fuselage_services.h"
#include "airshape/model/placement.h"
#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::tank {

/// One vessel of a tank as its element defines it: a model tank's `vessel`, a CPACS 3.5
/// fuselage tank's `hull`, or the `designParameters` of a CPACS 3.5 tank (which is then its
/// own only vessel).
struct Vessel {
  std::string uid;
  std::string xpath;
  /// Takes the vessel's own frame to the global one: its tank's placement, then its own
  /// transformation.
  model::Transform placement;
  /// Sections and segments, lofted as a fuselage's; null for a vessel of design parameters.
  std::shared_ptr<const schema::FuselageType> body;
  /// The design parameters (each absent where the element leaves it out).
  std::optional<double> cylinderRadius, cylinderLength;
  std::shared_ptr<const schema::DomeTypeType> dome;
  /// Its structure (walls, frames), read into the 3.5 type of a fuselage's; null without one.
  std::shared_ptr<const schema::FuselageStructureType> structure;
};

/// The vessel of this uID (a tankHull component, or a tank given by design parameters).
/// Throws Error naming the element when its numbers cannot be read.
std::shared_ptr<const Vessel> vesselNamed(const Configuration& configuration, const std::string& uid);

/// The uIDs of a tank's vessels, in document order (the tank's own for design parameters).
std::vector<std::string> vesselsOfTank(const Configuration& configuration, const std::string& tankUid);

/// The vessel's solid in the global frame: lofted by the fuselage plugin from sections and
/// segments, or revolved from design parameters (vessel_of_revolution.h).
NamedShape vesselSolid(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                       const Vessel& vessel);

}  // namespace airshape::tank
