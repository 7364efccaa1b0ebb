#include "fuselage_structure_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/fuselage/fuselage_list.h"

namespace airshape::structure {

namespace {

/// The first element of a fuselage structure list (`listOf` picks it from a structure) whose
/// uID is `uid`, in any fuselage of any model.
template <class Node, class ListOf>
FuselageElement<Node> findInFuselages(const Configuration& configuration, const std::string& uid, ListOf listOf) {
  for (std::size_t model = 0; model < model::modelCount(configuration); ++model)
    for (const schema::FuselageType* fuselage : fuselage::fuselagesOf(configuration, model)) {
      if (!fuselage->structure) continue;
      for (const Node* node : listOf(*fuselage->structure))
        if (node->uID == uid) return {node, fuselage, &*fuselage->structure, fuselage->uID, std::nullopt, nullptr};
    }
  return {};
}

}  // namespace

FuselageElement<schema::PressureBulkheadAssemblyPositionType> pressureBulkheadNamed(const Configuration& configuration,
                                                                                    const std::string& uid) {
  const auto found = findInFuselages<schema::PressureBulkheadAssemblyPositionType>(
      configuration, uid, [](const schema::FuselageStructureType& structure) {
        std::vector<const schema::PressureBulkheadAssemblyPositionType*> nodes;
        if (structure.pressureBulkheads)
          for (const auto& bulkhead : structure.pressureBulkheads->pressureBulkhead) nodes.push_back(&bulkhead);
        return nodes;
      });
  if (found.node == nullptr)
    throw Error(ErrorCode::InvalidArgument, "no fuselage pressure bulkhead with uID '" + uid + "'");
  return found;
}

namespace {

std::vector<const schema::WallSegmentType*> wallSegmentsOf(const schema::FuselageStructureType& structure) {
  std::vector<const schema::WallSegmentType*> nodes;
  if (structure.walls && structure.walls->wallSegments)
    for (const auto& wall : structure.walls->wallSegments->wallSegment)
      if (wall.uID) nodes.push_back(&wall);
  return nodes;
}

/// The element of this uID (`listOf` picks the candidates from a structure) in the vessel that
/// holds it (the component it lies in), if any.
template <class Node, class ListOf>
FuselageElement<Node> inVessel(const Configuration& configuration, const std::string& uid,
                               const tank::TankServices& tanks, ListOf listOf) {
  const long index = configuration.components().find(uid);
  if (index < 0) return {};
  const std::string& vessel = configuration.components().components()[static_cast<std::size_t>(index)].parentUid;
  if (vessel.empty() || configuration.components().named(vessel).nodeType != "tankHull") return {};
  const auto structure = tanks.vesselStructure(configuration, vessel);
  if (!structure) return {};
  for (const Node* node : listOf(*structure))
    if (node->uID == uid) {
      const auto body = tanks.vesselBody(configuration, vessel);
      return {node,
              body.get(),
              structure.get(),
              vessel,
              tanks.vesselPlacement(configuration, vessel),
              std::make_shared<std::pair<decltype(body), decltype(structure)>>(body, structure)};
    }
  return {};
}

/// The element of this uID in any fuselage, or else in a tank's vessel (when `tanks` is given).
template <class Node, class ListOf>
FuselageElement<Node> inFuselagesOrVessels(const Configuration& configuration, const std::string& uid,
                                           const tank::TankServices* tanks, ListOf listOf) {
  auto found = findInFuselages<Node>(configuration, uid, listOf);
  if (found.node == nullptr && tanks != nullptr) found = inVessel<Node>(configuration, uid, *tanks, listOf);
  return found;
}

}  // namespace

FuselageElement<schema::WallSegmentType> wallSegmentNamed(const Configuration& configuration, const std::string& uid,
                                                          const tank::TankServices* tanks) {
  const auto found = inFuselagesOrVessels<schema::WallSegmentType>(configuration, uid, tanks, wallSegmentsOf);
  if (found.node == nullptr) throw Error(ErrorCode::InvalidArgument, "no wall segment with uID '" + uid + "'");
  return found;
}

FuselageElement<schema::CrossBeamAssemblyPositionType> crossBeamNamed(const Configuration& configuration,
                                                                      const std::string& uid) {
  const auto found = findInFuselages<schema::CrossBeamAssemblyPositionType>(
      configuration, uid, [](const schema::FuselageStructureType& structure) {
        std::vector<const schema::CrossBeamAssemblyPositionType*> nodes;
        if (structure.cargoCrossBeams)
          for (const auto& beam : structure.cargoCrossBeams->cargoCrossBeam) nodes.push_back(&beam);
        if (structure.paxCrossBeams)
          for (const auto& beam : structure.paxCrossBeams->paxCrossBeam) nodes.push_back(&beam);
        return nodes;
      });
  if (found.node == nullptr) throw Error(ErrorCode::InvalidArgument, "no fuselage cross beam with uID '" + uid + "'");
  return found;
}

FuselageElement<schema::CrossBeamStrutAssemblyPositionType> crossBeamStrutNamed(const Configuration& configuration,
                                                                                const std::string& uid) {
  const auto found = findInFuselages<schema::CrossBeamStrutAssemblyPositionType>(
      configuration, uid, [](const schema::FuselageStructureType& structure) {
        std::vector<const schema::CrossBeamStrutAssemblyPositionType*> nodes;
        if (structure.cargoCrossBeamStruts)
          for (const auto& strut : structure.cargoCrossBeamStruts->cargoCrossBeamStrut) nodes.push_back(&strut);
        if (structure.paxCrossBeamStruts)
          for (const auto& strut : structure.paxCrossBeamStruts->paxCrossBeamStrut) nodes.push_back(&strut);
        return nodes;
      });
  if (found.node == nullptr)
    throw Error(ErrorCode::InvalidArgument, "no fuselage cross-beam strut with uID '" + uid + "'");
  return found;
}

FuselageElement<schema::LongFloorBeamType> longFloorBeamNamed(const Configuration& configuration,
                                                              const std::string& uid) {
  const auto found = findInFuselages<schema::LongFloorBeamType>(
      configuration, uid, [](const schema::FuselageStructureType& structure) {
        std::vector<const schema::LongFloorBeamType*> nodes;
        if (structure.longFloorBeams)
          for (const auto& beam : structure.longFloorBeams->longFloorBeam) nodes.push_back(&beam);
        return nodes;
      });
  if (found.node == nullptr) throw Error(ErrorCode::InvalidArgument, "no long floor beam with uID '" + uid + "'");
  return found;
}

FuselageElement<schema::DoorAssemblyPositionType> doorNamed(const Configuration& configuration,
                                                            const std::string& uid) {
  const auto found = findInFuselages<schema::DoorAssemblyPositionType>(
      configuration, uid, [](const schema::FuselageStructureType& structure) {
        std::vector<const schema::DoorAssemblyPositionType*> nodes;
        if (structure.cargoDoors)
          for (const auto& door : structure.cargoDoors->cargoDoor) nodes.push_back(&door);
        if (structure.paxDoors)
          for (const auto& door : structure.paxDoors->paxDoor) nodes.push_back(&door);
        return nodes;
      });
  if (found.node == nullptr) throw Error(ErrorCode::InvalidArgument, "no fuselage door with uID '" + uid + "'");
  return found;
}

FuselageElement<schema::FrameType> frameElementNamed(const Configuration& configuration, const std::string& uid,
                                                     const tank::TankServices* tanks) {
  const auto found = inFuselagesOrVessels<schema::FrameType>(configuration, uid, tanks,
                                                             [](const schema::FuselageStructureType& structure) {
                                                               std::vector<const schema::FrameType*> nodes;
                                                               if (structure.frames)
                                                                 for (const auto& frame : structure.frames->frame)
                                                                   nodes.push_back(&frame);
                                                               return nodes;
                                                             });
  if (found.node == nullptr) throw Error(ErrorCode::InvalidArgument, "no fuselage frame with uID '" + uid + "'");
  return found;
}

FuselageElement<schema::StringerType> stringerElementNamed(const Configuration& configuration, const std::string& uid,
                                                           const tank::TankServices* tanks) {
  const auto found = inFuselagesOrVessels<schema::StringerType>(
      configuration, uid, tanks, [](const schema::FuselageStructureType& structure) {
        std::vector<const schema::StringerType*> nodes;
        if (structure.stringers)
          for (const auto& stringer : structure.stringers->stringer) nodes.push_back(&stringer);
        return nodes;
      });
  if (found.node == nullptr) throw Error(ErrorCode::InvalidArgument, "no fuselage stringer with uID '" + uid + "'");
  return found;
}

const schema::StringerType& stringerNamed(const schema::FuselageStructureType& structure, const std::string& uid,
                                          const std::string& where) {
  if (structure.stringers)
    for (const auto& stringer : structure.stringers->stringer)
      if (stringer.uID == uid) return stringer;
  throw Error(ErrorCode::InvalidModel, "stringerUID '" + uid + "' names no stringer of this fuselage", {}, where);
}

const schema::FrameType& frameNamed(const schema::FuselageStructureType& structure, const std::string& uid,
                                    const std::string& where) {
  if (structure.frames)
    for (const auto& frame : structure.frames->frame)
      if (frame.uID == uid) return frame;
  throw Error(ErrorCode::InvalidModel, "frameUID '" + uid + "' names no frame of this fuselage", {}, where);
}

const schema::WallPositionType& wallPositionNamed(const schema::FuselageStructureType& structure,
                                                  const std::string& uid, const std::string& where) {
  if (structure.walls && structure.walls->wallPositions)
    for (const auto& position : structure.walls->wallPositions->wallPosition)
      if (position.uID && *position.uID == uid) return position;
  throw Error(ErrorCode::InvalidModel, "wallPositionUID '" + uid + "' names no wall position of this fuselage", {},
              where);
}

}  // namespace airshape::structure
