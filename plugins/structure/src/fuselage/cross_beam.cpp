#include "cross_beam.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <BRepAlgoAPI_Section.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Lin.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "compounds.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"

namespace airshape::structure {

namespace {

/// The parts inside the fuselage of the line through `through` along `along`: between
/// consecutive points where it crosses the skin; nothing when it does not cross it an even
/// number of times (a line touching the skin), which the caller then sections.
std::optional<TopoDS_Shape> insideAlong(const FuselageFrame& fuselage, const gp_Pnt& through, const gp_Dir& along) {
  IntCurvesFace_ShapeIntersector intersector;
  const double tolerance = 1e-9 * fuselage.reach();
  intersector.Load(fuselage.solid(), tolerance);
  intersector.Perform(gp_Lin(through, along), -fuselage.reach(), fuselage.reach());
  if (!intersector.IsDone()) return std::nullopt;
  std::vector<double> crossings;
  for (int i = 1; i <= intersector.NbPnt(); ++i) crossings.push_back(intersector.WParameter(i));
  std::sort(crossings.begin(), crossings.end());
  // A crossing on an edge between two skin faces is found on both.
  crossings.erase(std::unique(crossings.begin(), crossings.end(),
                              [&](double a, double b) { return std::abs(a - b) <= 10.0 * tolerance; }),
                  crossings.end());
  if (crossings.empty() || crossings.size() % 2 != 0) return std::nullopt;
  std::vector<TopoDS_Shape> pieces;
  for (std::size_t k = 0; k < crossings.size(); k += 2)
    pieces.push_back(BRepBuilderAPI_MakeEdge(gp_Lin(through, along), crossings[k], crossings[k + 1]).Edge());
  return compoundOf(pieces);
}

/// The cross beam's axis in the global frame: where its height's level meets its frame's
/// station plane, inside the fuselage.
TopoDS_Shape beamAxis(const Configuration& configuration,
                      const FuselageElement<schema::CrossBeamAssemblyPositionType>& beam) {
  const schema::FrameType& frame = frameNamed(*beam.structure, beam.node->frameUID, beam.node->xpath + "/frameUID");
  const FuselageFrame fuselage(configuration, *beam.fuselage);
  const gp_Pnt through = fuselage.toGlobal(gp_Pnt(fuselage.stationX(frame), 0.0, beam.node->positionZ));
  if (const auto axis = insideAlong(fuselage, through, fuselage.toGlobal(gp_Dir(0, 1, 0)))) return *axis;
  const gp_Pln station = fuselage.station(frame);
  const TopoDS_Compound section = compoundOf(fuselage.crossSection(station.Location(), station.Axis().Direction()));
  const gp_Pln level(fuselage.toGlobal(gp_Pnt(0, 0, beam.node->positionZ)), fuselage.toGlobal(gp_Dir(0, 0, 1)));
  BRepAlgoAPI_Section cut(section, BRepBuilderAPI_MakeFace(level, -fuselage.reach(), fuselage.reach(),
                                                           -fuselage.reach(), fuselage.reach()));
  if (!cut.IsDone()) throw Error(ErrorCode::InvalidModel, "the cross beam's plane cannot be cut", {}, beam.node->xpath);
  TopExp_Explorer any(cut.Shape(), TopAbs_EDGE);
  if (!any.More())
    throw Error(ErrorCode::InvalidModel, "the cross beam's height lies outside the fuselage at its frame", {},
                beam.node->xpath + "/positionZ");
  return cut.Shape();
}

/// The point of a cross beam at `y` (fuselage coordinates), which must lie on the beam;
/// otherwise throws Error naming `where`.
gp_Pnt pointOnBeam(const Configuration& configuration, const FuselageFrame& fuselage,
                   const FuselageElement<schema::CrossBeamAssemblyPositionType>& beam, double y,
                   const std::string& where) {
  const schema::FrameType& frame = frameNamed(*beam.structure, beam.node->frameUID, beam.node->xpath + "/frameUID");
  const gp_Pnt point = fuselage.toGlobal(gp_Pnt(fuselage.stationX(frame), y, beam.node->positionZ));
  BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(point).Vertex(), beamAxis(configuration, beam));
  if (!distance.IsDone() || distance.Value() > 1e-6)
    throw Error(ErrorCode::InvalidModel, "the position lies beyond the ends of its cross beam", {}, where);
  return point;
}

}  // namespace

NamedShape crossBeam(const Configuration& configuration, const std::string& uid) {
  return edgesOf(beamAxis(configuration, crossBeamNamed(configuration, uid)));
}

NamedShape crossBeamStrut(const Configuration& configuration, const std::string& uid) {
  const auto strut = crossBeamStrutNamed(configuration, uid);
  const schema::CrossBeamStrutAssemblyPositionType& node = *strut.node;
  const auto beam = crossBeamNamed(configuration, node.crossBeamUID);
  const schema::FrameType& frame = frameNamed(*strut.structure, node.frameUID, node.xpath + "/frameUID");
  const FuselageFrame fuselage(configuration, *strut.fuselage);
  const gp_Pnt onBeam =
      pointOnBeam(configuration, fuselage, beam, node.positionYAtCrossBeam, node.xpath + "/positionYAtCrossBeam");
  // Along the beam's plane turned by angleX − 90° about the x axis, from straight down.
  const double turn = (node.angleX.value_or(90.0) - 90.0) * M_PI / 180.0;
  const gp_Dir down = fuselage.toGlobal(gp_Dir(0.0, std::sin(turn), -std::cos(turn)));
  const gp_Pnt start =
      fuselage.toGlobal(gp_Pnt(fuselage.stationX(frame), node.positionYAtCrossBeam, beam.node->positionZ));
  const gp_Pnt onFrame = fuselage.skinAhead(start, down, node.xpath);
  return edgesOf(BRepBuilderAPI_MakeEdge(onBeam, onFrame).Edge());
}

NamedShape longFloorBeam(const Configuration& configuration, const std::string& uid) {
  const auto floorBeam = longFloorBeamNamed(configuration, uid);
  const auto& positions = floorBeam.node->longFloorBeamPosition;
  if (positions.size() < 2)
    throw Error(ErrorCode::InvalidModel, "a long floor beam needs at least two positions", {}, floorBeam.node->xpath);
  const FuselageFrame fuselage(configuration, *floorBeam.fuselage);
  std::vector<gp_Pnt> points;
  for (const schema::LongFloorBeamPositionType& position : positions)
    points.push_back(pointOnBeam(configuration, fuselage, crossBeamNamed(configuration, position.crossBeamUID),
                                 position.positionY, position.xpath + "/positionY"));
  std::vector<TopoDS_Shape> pieces;
  for (std::size_t k = 1; k < points.size(); ++k)
    if (!points[k].IsEqual(points[k - 1], 1e-9 * fuselage.reach()))
      pieces.push_back(BRepBuilderAPI_MakeEdge(points[k - 1], points[k]).Edge());
  return edgesOf(compoundOf(pieces));
}

}  // namespace airshape::structure
