#include "spar_list.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/placement.h"
#include "component_segments.h"

namespace airshape::structure {

namespace {

/// An older files' spar point (`sparPoint` with eta, xsi and referenceUID, as CPACS 3.0 files
/// of some tools write it): the same point as sparPositionEtaXsi, read with a warning.
bool readSparPoint(const Configuration& configuration, const std::string& xpath, SparPosition& position) {
  const std::string point = xpath + "/sparPoint";
  try {
    position.eta = std::stod(configuration.value(point + "/eta"));
    position.xsi = std::stod(configuration.value(point + "/xsi"));
  } catch (const std::exception&) {  // no sparPoint, or not numbers
    return false;
  }
  model::fraction(position.eta, point + "/eta");
  model::fraction(position.xsi, point + "/xsi");
  try {
    position.referenceUid = configuration.value(point + "/referenceUID");
  } catch (const Error&) {  // a component segment eta and xsi
  }
  configuration.warnAboutGeometry(
      {Problem::Severity::Warning, point, "a spar point in an older form; read as sparPositionEtaXsi"});
  return true;
}

}  // namespace

SparPosition sparPositionOf(const Configuration& configuration, const schema::SparPositionType& node) {
  SparPosition position;
  position.uid = node.uID;
  position.xpath = node.xpath;
  if (node.sparPositionEtaXsi) {
    position.eta = model::fraction(node.sparPositionEtaXsi->eta, node.xpath + "/sparPositionEtaXsi/eta");
    position.xsi = model::fraction(node.sparPositionEtaXsi->xsi, node.xpath + "/sparPositionEtaXsi/xsi");
    position.referenceUid = node.sparPositionEtaXsi->referenceUID;
  } else if (node.sparPositionRib) {
    position.kind = SparPosition::Kind::OnRib;
    position.xsi = model::fraction(node.sparPositionRib->xsi, node.xpath + "/sparPositionRib/xsi");
    position.ribsUid = node.sparPositionRib->ribDefinitionUID;
    position.ribNumber = node.sparPositionRib->ribNumber.value_or(1);
  } else if (node.sparPositionCurve) {
    position.kind = SparPosition::Kind::OnCurve;
    position.eta = model::fraction(node.sparPositionCurve->eta, node.xpath + "/sparPositionCurve/eta");
    position.referenceUid = node.sparPositionCurve->referenceUID;
  } else if (!readSparPoint(configuration, node.xpath, position)) {
    throw Error(ErrorCode::InvalidModel,
                "the spar position has none of sparPositionEtaXsi, sparPositionRib and sparPositionCurve", {},
                node.xpath);
  }
  return position;
}

namespace {

SparSegment segmentOf(const Configuration& configuration, const schema::SparSegmentType& node,
                      const schema::WingSparType& spars, const StructureHost& host) {
  SparSegment segment{node.uID, node.xpath, host.componentSegment->uID, host.wing->uID, {}, host.deviceUid};
  if (!node.sparPositionUIDs) return segment;
  for (const std::string& uid : node.sparPositionUIDs->sparPositionUID) {
    const schema::SparPositionType* found = nullptr;
    if (spars.sparPositions)
      for (const auto& position : spars.sparPositions->sparPosition)
        if (position.uID == uid && found == nullptr) found = &position;
    if (found == nullptr)
      throw Error(ErrorCode::InvalidModel, "sparPositionUID '" + uid + "' names no spar position of its spars", {},
                  node.xpath + "/sparPositionUIDs");
    segment.positions.push_back(sparPositionOf(configuration, *found));
  }
  return segment;
}

}  // namespace

SparSegment sparSegmentNamed(const Configuration& configuration, const std::string& uid) {
  for (const StructureHost& host : everyStructure(configuration)) {
    if (!host.structure->spars) continue;
    const schema::WingSparType& spars = *host.structure->spars;
    if (!spars.sparSegments) continue;
    for (const auto& segment : spars.sparSegments->sparSegment)
      if (segment.uID == uid) return segmentOf(configuration, segment, spars, host);
  }
  throw Error(ErrorCode::InvalidArgument, "no spar segment with uID '" + uid + "'");
}

}  // namespace airshape::structure
