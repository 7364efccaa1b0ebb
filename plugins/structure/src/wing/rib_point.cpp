#include "rib_point.h"

#include "airshape/configuration.h"
#include "airshape/construction_guard.h"
#include "airshape/error.h"
#include "rib_cutter.h"
#include "rib_faces.h"
#include "rib_list.h"
#include "spar_list.h"

namespace airshape::structure {

gp_Pln ribPlane(const Configuration& configuration, const StructureFrame& frame, const std::string& ribsUid,
                long long number, const std::string& where) {
  try {
    // Placed without cutting the ribs out of the wing, which costs seconds for a long set.
    const RibPlacement rib = ribPlacement(configuration, ribsDefinitionNamed(configuration, ribsUid), frame, number);
    const gp_Vec normal = rib.direction.Crossed(rib.up);
    if (normal.Magnitude() < 1e-12) throw Error(ErrorCode::InvalidModel, "the rib has no plane");
    return gp_Pln(rib.point, gp_Dir(normal));
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), error.message(), {}, where);
  }
}

gp_Pnt pointOnRib(const Configuration& configuration, const StructureFrame& frame, const std::string& ribsUid,
                  long long number, double xsi, const std::string& where) {
  // A spar on a rib of a definition whose ribs end at that spar would be built for ever.
  const ConstructionGuard guard(
      "ribs", ribsUid, "the ribs of '" + ribsUid + "' and a spar positioned on them depend on each other", where);
  const gp_Pln plane = ribPlane(configuration, frame, ribsUid, number, where);
  const RibsDefinition ribs = ribsDefinitionNamed(configuration, ribsUid);
  const RibCutter cutter(configuration, frame, *ribs.structure);
  const std::string* start = nullptr;
  const std::string* end = nullptr;
  if (ribs.node->ribsPositioning) {
    start = &ribs.node->ribsPositioning->ribStart;
    end = &ribs.node->ribsPositioning->ribEnd;
  } else if (ribs.node->ribExplicitPositioning) {
    start = &ribs.node->ribExplicitPositioning->ribStart;
    end = &ribs.node->ribExplicitPositioning->ribEnd;
  } else {
    throw Error(ErrorCode::InvalidModel, "ribs definition '" + ribsUid + "' places no rib", {}, where);
  }
  auto crossing = [&](const std::string& line) {
    const geometry::Polyline border = cutter.frame().lineNamed(line, where);
    const auto share = border.crossing(plane.Location(), gp_Vec(plane.Axis().Direction()));
    if (!share) throw Error(ErrorCode::InvalidModel, "the rib does not reach its border '" + line + "'", {}, where);
    return border.at(*share);
  };
  const gp_Pnt from = crossing(*start), to = crossing(*end);
  return gp_Pnt(from.XYZ() + xsi * (to.XYZ() - from.XYZ()));
}

}  // namespace airshape::structure
