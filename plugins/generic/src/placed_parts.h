#pragma once

#include <string>

#include "airshape/fuselage/fuselage_services.h"
#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::generic {

/// A system component (systems/genericSystems/genericSystem/components/component): the
/// geometry of the system element its systemElementUID names, placed by its transformation,
/// translated by the origin of its parentUID where it names a component.
NamedShape systemComponentShape(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                                const std::string& uid);

/// A deck component (a seat module, galley, lavatory, ...): the geometry of the deck element
/// its deckElementUID names, placed by its transformation within its deck.
NamedShape deckComponentShape(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                              const std::string& uid);

/// An external object (genericGeometryComponents/genericGeometryComponent): the CAD file it
/// links, placed by its transformation, translated by its parent's origin.
NamedShape externalObjectShape(const Configuration& configuration, const std::string& uid);

/// A system or deck: the compound of its components that have a shape (those of
/// `childType` inside it). Throws NoShape when none has one.
NamedShape compoundOfParts(const Configuration& configuration, const std::string& uid, const std::string& childType);

}  // namespace airshape::generic
