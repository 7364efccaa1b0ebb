#include "rib_point.h"

#include <set>

#include "airshape/configuration.h"
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

namespace {

/// The ribs definitions whose ribs are being looked at on this thread: a spar on a rib of a
/// definition whose ribs end at that spar would be built forever.
thread_local std::set<std::string> ribsInUse;

class RibsGuard {
 public:
  RibsGuard(const std::string& uid, const std::string& where) : uid_(uid) {
    if (!ribsInUse.insert(uid).second)
      throw Error(ErrorCode::InvalidModel,
                  "the ribs of '" + uid + "' and a spar positioned on them depend on each other", {}, where);
  }
  ~RibsGuard() { ribsInUse.erase(uid_); }
  RibsGuard(const RibsGuard&) = delete;
  RibsGuard& operator=(const RibsGuard&) = delete;

 private:
  std::string uid_;
};

}  // namespace

gp_Pnt pointOnRib(const Configuration& configuration, const StructureFrame& frame, const std::string& ribsUid,
                  long long number, double xsi, const std::string& where) {
  const RibsGuard guard(ribsUid, where);
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
    const Polyline border = cutter.frame().lineNamed(line, where);
    const auto share = border.crossing(plane.Location(), gp_Vec(plane.Axis().Direction()));
    if (!share) throw Error(ErrorCode::InvalidModel, "the rib does not reach its border '" + line + "'", {}, where);
    return border.at(*share);
  };
  const gp_Pnt from = crossing(*start), to = crossing(*end);
  return gp_Pnt(from.XYZ() + xsi * (to.XYZ() - from.XYZ()));
}

}  // namespace airshape::structure
