#pragma once

#include <memory>
#include <optional>
#include <string>

#include "airshape/model/placement.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "airshape/tank/tank_services.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// An element of a fuselage's (or a tank vessel's) structure and what holds it.
template <class Node>
struct FuselageElement {
  const Node* node = nullptr;
  const schema::FuselageType* fuselage = nullptr;  ///< null in a vessel of design parameters
  const schema::FuselageStructureType* structure = nullptr;
  /// The component it is positioned in: a fuselage, or a tank's vessel (then placed by
  /// `vesselPlacement`, its structure kept alive by `owner`).
  std::string hostUid;
  std::optional<model::Transform> vesselPlacement;
  std::shared_ptr<const void> owner;
};

/// The pressure bulkhead (fuselage/structure/pressureBulkheads) with this uID in any model.
/// Throws Error when none has it.
FuselageElement<schema::PressureBulkheadAssemblyPositionType> pressureBulkheadNamed(const Configuration& configuration,
                                                                                    const std::string& uid);

/// The wall segment with this uID in any fuselage, or in a tank's vessel (found through the
/// tank plugin's services, when given). Throws Error when none has it.
FuselageElement<schema::WallSegmentType> wallSegmentNamed(const Configuration& configuration, const std::string& uid,
                                                          const tank::TankServices* tanks);

/// The cargo or passenger cross beam with this uID in any model. Throws Error when none has it.
FuselageElement<schema::CrossBeamAssemblyPositionType> crossBeamNamed(const Configuration& configuration,
                                                                      const std::string& uid);

/// The cargo or passenger cross-beam strut with this uID in any model. Throws Error when none
/// has it.
FuselageElement<schema::CrossBeamStrutAssemblyPositionType> crossBeamStrutNamed(const Configuration& configuration,
                                                                                const std::string& uid);

/// The long floor beam with this uID in any model. Throws Error when none has it.
FuselageElement<schema::LongFloorBeamType> longFloorBeamNamed(const Configuration& configuration,
                                                              const std::string& uid);

/// The cargo or passenger door with this uID in any model. Throws Error when none has it.
FuselageElement<schema::DoorAssemblyPositionType> doorNamed(const Configuration& configuration, const std::string& uid);

/// The frame with this uID in any fuselage, or in a tank's vessel (found through the tank
/// plugin's services, when given). Throws Error when none has it.
FuselageElement<schema::FrameType> frameElementNamed(const Configuration& configuration, const std::string& uid,
                                                     const tank::TankServices* tanks);

/// The stringer with this uID in any fuselage or tank vessel, as frameElementNamed. Throws Error
/// when none has it.
FuselageElement<schema::StringerType> stringerElementNamed(const Configuration& configuration, const std::string& uid,
                                                           const tank::TankServices* tanks);

/// The stringer of a fuselage structure with this uID; throws Error naming `where` when none has
/// it.
const schema::StringerType& stringerNamed(const schema::FuselageStructureType& structure, const std::string& uid,
                                          const std::string& where);

/// The frame of a fuselage structure with this uID; throws Error naming `where` when none has it.
const schema::FrameType& frameNamed(const schema::FuselageStructureType& structure, const std::string& uid,
                                    const std::string& where);

/// The wall position of a fuselage structure with this uID; throws Error naming `where` when
/// none has it.
const schema::WallPositionType& wallPositionNamed(const schema::FuselageStructureType& structure,
                                                  const std::string& uid, const std::string& where);

}  // namespace airshape::structure
