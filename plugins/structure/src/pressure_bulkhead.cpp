#include "pressure_bulkhead.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "named_faces.h"

namespace airshape::structure {

NamedShape pressureBulkhead(const Configuration& configuration, const std::string& uid) {
  const auto bulkhead = pressureBulkheadNamed(configuration, uid);
  const schema::FrameType& frame =
      frameNamed(*bulkhead.structure, bulkhead.node->frameUID, bulkhead.node->xpath + "/frameUID");
  const FuselageFrame fuselage(configuration, *bulkhead.fuselage);
  const gp_Pln station = fuselage.station(frame);
  std::vector<TopoDS_Face> faces;
  try {
    faces = fuselage.crossSection(station.Location(), station.Axis().Direction());
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, "the fuselage cannot be cut at the bulkhead's frame", {}, frame.xpath);
  }
  NamedFaces shape;
  shape.add(uid + "/bulkhead", faces);
  if (shape.empty())
    throw Error(ErrorCode::InvalidModel, "the bulkhead's frame lies outside the fuselage", {}, frame.xpath);
  return shape.shape();
}

}  // namespace airshape::structure
