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
  if (frame.framePosition.size() != 1)
    throw Error(ErrorCode::NotImplemented,
                "bulkheads on frames of " + std::to_string(frame.framePosition.size()) +
                    " frame positions are not built yet (one position: a plane station)",
                {}, frame.xpath);
  const schema::StringerFramePositionType& position = frame.framePosition[0];
  if (!position.positionX)
    throw Error(ErrorCode::NotImplemented, "frame positions placed by a section element are not built yet", {},
                position.xpath);
  const FuselageFrame fuselage(configuration, *bulkhead.fuselage);
  const gp_Pnt station = fuselage.toGlobal(gp_Pnt(*position.positionX, position.referenceY, position.referenceZ));
  std::vector<TopoDS_Face> faces;
  try {
    faces = fuselage.crossSection(station, fuselage.toGlobal(gp_Dir(1, 0, 0)));
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, "the fuselage cannot be cut at the bulkhead's frame", {}, frame.xpath);
  }
  NamedFaces shape;
  shape.add(uid + "/bulkhead", faces);
  if (shape.empty())
    throw Error(ErrorCode::InvalidModel, "the bulkhead's frame lies outside the fuselage", {}, position.xpath);
  return shape.shape();
}

}  // namespace airshape::structure
