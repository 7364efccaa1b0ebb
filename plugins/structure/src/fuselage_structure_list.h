#pragma once

#include <string>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// An element of a fuselage's structure and the fuselage that holds it.
template <class Node>
struct FuselageElement {
  const Node* node = nullptr;
  const schema::FuselageType* fuselage = nullptr;
  const schema::FuselageStructureType* structure = nullptr;
};

/// The pressure bulkhead (fuselage/structure/pressureBulkheads) with this uID in any model.
/// Throws Error when none has it.
FuselageElement<schema::PressureBulkheadAssemblyPositionType> pressureBulkheadNamed(const Configuration& configuration,
                                                                                    const std::string& uid);

/// The wall segment (fuselage/structure/walls) with this uID in any model. Throws Error when
/// none has it.
FuselageElement<schema::WallSegmentType> wallSegmentNamed(const Configuration& configuration, const std::string& uid);

/// The cargo or passenger cross beam with this uID in any model. Throws Error when none has it.
FuselageElement<schema::CrossBeamAssemblyPositionType> crossBeamNamed(const Configuration& configuration,
                                                                      const std::string& uid);

/// The cargo or passenger cross-beam strut with this uID in any model. Throws Error when none
/// has it.
FuselageElement<schema::CrossBeamStrutAssemblyPositionType> crossBeamStrutNamed(const Configuration& configuration,
                                                                                const std::string& uid);

/// The frame of a fuselage structure with this uID; throws Error naming `where` when none has it.
const schema::FrameType& frameNamed(const schema::FuselageStructureType& structure, const std::string& uid,
                                    const std::string& where);

/// The wall position of a fuselage structure with this uID; throws Error naming `where` when
/// none has it.
const schema::WallPositionType& wallPositionNamed(const schema::FuselageStructureType& structure,
                                                  const std::string& uid, const std::string& where);

}  // namespace airshape::structure
