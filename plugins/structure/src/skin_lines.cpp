#include "skin_lines.h"

#include <BRepAlgoAPI_Section.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <TopExp_Explorer.hxx>

#include "airshape/error.h"
#include "compounds.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "position_rays.h"

namespace airshape::structure {

namespace {

/// Where the tool faces meet the fuselage's skin, as an edge shape; throws Error naming `where`
/// when they do not meet.
NamedShape onSkin(const FuselageFrame& fuselage, const std::vector<TopoDS_Face>& tools, const std::string& where) {
  BRepAlgoAPI_Section section(compoundOf(fuselage.skinFaces()), compoundOf(tools), false);
  section.SetRunParallel(true);
  section.SetNonDestructive(true);  // the skin is shared, cached geometry
  section.Build();
  if (!section.IsDone() || section.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the line on the fuselage's skin cannot be found", {}, where);
  if (!TopExp_Explorer(section.Shape(), TopAbs_EDGE).More())
    throw Error(ErrorCode::InvalidModel, "the positions' rays do not meet the fuselage's skin", {}, where);
  return edgesOf(section.Shape());
}

}  // namespace

NamedShape frameLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid) {
  const auto frame = frameElementNamed(configuration, uid, tanks);
  const FuselageFrame fuselage =
      FuselageFrame::ofHost(configuration, frame.hostUid, frame.fuselage, frame.vesselPlacement);
  if (frame.node->framePosition.size() > 1)
    return onSkin(fuselage, frameSweep(fuselage, *frame.node, fuselage.localReach()), frame.node->xpath);
  const gp_Pln station = fuselage.station(*frame.node);
  const double reach = fuselage.reach();
  return onSkin(fuselage, {BRepBuilderAPI_MakeFace(station, -reach, reach, -reach, reach).Face()}, frame.node->xpath);
}

NamedShape stringerLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid) {
  const auto stringer = stringerElementNamed(configuration, uid, tanks);
  const FuselageFrame fuselage =
      FuselageFrame::ofHost(configuration, stringer.hostUid, stringer.fuselage, stringer.vesselPlacement);
  const StringerPath path(fuselage, *stringer.node);
  if (path.lastX() <= path.firstX())
    throw Error(ErrorCode::InvalidModel, "the stringer's positions lie at one station: it has no length", {},
                stringer.node->xpath);
  return onSkin(fuselage, path.surface(fuselage, path.firstX(), path.lastX(), fuselage.localReach()),
                stringer.node->xpath);
}

}  // namespace airshape::structure
