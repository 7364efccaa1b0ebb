#include "fuselage_door.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/skin_section.h"
#include "airshape/geometry/skin_split.h"
#include "compounds.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "named_faces.h"
#include "position_rays.h"

namespace airshape::structure {

namespace {

/// The angle of a direction about the fuselage's x axis in the stringers' convention (0 up,
/// a quarter turn towards −y).
double angleAboutX(const gp_Vec& direction) { return std::atan2(-direction.Y(), direction.Z()); }

/// An angle brought into (−π, π].
double wrapped(double angle) {
  while (angle > M_PI) angle -= 2.0 * M_PI;
  while (angle <= -M_PI) angle += 2.0 * M_PI;
  return angle;
}

/// Whether a point (fuselage coordinates) lies between the two stringers the shorter way round,
/// seen from the midpoint of their reference points at its station.
bool betweenStringers(const FuselageFrame& fuselage, const StringerPath& first, const StringerPath& last,
                      const gp_Pnt& point, const std::string& where) {
  const PositionRay a = first.rayAt(point.X());
  const PositionRay b = last.rayAt(point.X());
  const gp_Pnt centre(0.5 * (a.origin.XYZ() + b.origin.XYZ()));
  auto angleOnSkin = [&](const PositionRay& ray) {
    const gp_Pnt hit =
        fuselage.skinAhead(fuselage.toGlobal(ray.origin), fuselage.toGlobal(gp_Dir(ray.direction)), where);
    return angleAboutX(gp_Vec(centre, fuselage.toLocal(hit)));
  };
  const double start = angleOnSkin(a);
  const double width = wrapped(angleOnSkin(b) - start);
  const double turn = wrapped(angleAboutX(gp_Vec(centre, point)) - start);
  return width >= 0.0 ? turn > 0.0 && turn < width : turn < 0.0 && turn > width;
}

/// Whether a face's box reaches between two stations (fuselage x): the skin faces a door can
/// lie on, the only ones worth splitting.
bool reachesStations(const FuselageFrame& fuselage, const TopoDS_Face& face, double fromX, double toX) {
  Bnd_Box box;
  BRepBndLib::Add(face, box);
  double xMin = 0, yMin = 0, zMin = 0, xMax = 0, yMax = 0, zMax = 0;
  box.Get(xMin, yMin, zMin, xMax, yMax, zMax);
  double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
  for (const double x : {xMin, xMax})
    for (const double y : {yMin, yMax})
      for (const double z : {zMin, zMax}) {
        const double local = fuselage.toLocal(gp_Pnt(x, y, z)).X();
        low = std::min(low, local), high = std::max(high, local);
      }
  return high >= fromX && low <= toX;
}

/// The frame's station (fuselage x); `field` names the reference in the door.
double frameStation(const FuselageFrame& fuselage, const FuselageElement<schema::DoorAssemblyPositionType>& door,
                    const std::string& frameUid, const std::string& field) {
  return fuselage.stationX(frameNamed(*door.structure, frameUid, door.node->xpath + "/" + field));
}

/// The loop around a door on the skin: along the first stringer's rays from the start to the end
/// station, across the end frame's plane to the last stringer, back along it and across the
/// start frame's plane (the rays between two stringers' the shorter way round), global frame.
geometry::RuledLoop doorLoop(const FuselageFrame& fuselage, const StringerPath& first, const StringerPath& last,
                             double fromX, double toX) {
  geometry::RuledLoop loop;
  loop.rays = true;
  auto add = [&](const PositionRay& ray) {
    const gp_Pnt origin = fuselage.toGlobal(ray.origin);
    loop.points.push_back(origin);
    loop.directions.push_back(gp_Vec(origin, fuselage.toGlobal(ray.origin.Translated(ray.direction))));
  };
  for (const auto& span : first.spans(fromX, toX)) add(span.first);
  add(first.rayAt(toX));
  const std::vector<RaySpan> back = last.spans(fromX, toX);
  add(last.rayAt(toX));
  for (auto span = back.rbegin(); span != back.rend(); ++span) add(span->first);
  return loop;
}

/// The skin faces that reach between the stations split by the two frame planes and the two
/// stringers' swept surfaces, which run a little beyond the frames so that the cuts meet.
std::vector<TopoDS_Face> splitByFramesAndStringers(const FuselageFrame& fuselage, const StringerPath& first,
                                                   const StringerPath& last, double fromX, double toX,
                                                   const std::string& where) {
  TopTools_ListOfShape arguments, tools;
  for (const TopoDS_Face& face : fuselage.skinFaces())
    if (reachesStations(fuselage, face, fromX, toX)) arguments.Append(face);
  const double reach = fuselage.reach();
  for (const double x : {fromX, toX})
    tools.Append(BRepBuilderAPI_MakeFace(gp_Pln(fuselage.toGlobal(gp_Pnt(x, 0, 0)), fuselage.toGlobal(gp_Dir(1, 0, 0))),
                                         -reach, reach, -reach, reach)
                     .Face());
  const double margin = 0.05 * (toX - fromX);
  for (const StringerPath* stringer : {&first, &last})
    for (const TopoDS_Face& face : stringer->surface(fuselage, fromX - margin, toX + margin, fuselage.localReach()))
      tools.Append(face);
  BRepAlgoAPI_Splitter splitter;
  splitter.SetArguments(arguments);
  splitter.SetTools(tools);
  splitter.SetRunParallel(true);
  splitter.SetNonDestructive(true);  // the fuselage's skin is shared, cached geometry
  splitter.Build();
  if (!splitter.IsDone() || splitter.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the fuselage's skin cannot be cut at the door's frames and stringers", {},
                where);
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer face(splitter.Shape(), TopAbs_FACE); face.More(); face.Next())
    faces.push_back(TopoDS::Face(face.Current()));
  return faces;
}

}  // namespace

NamedShape fuselageDoor(const Configuration& configuration, const std::string& uid) {
  const auto door = doorNamed(configuration, uid);
  const schema::DoorAssemblyPositionType& node = *door.node;
  const FuselageFrame fuselage(configuration, *door.fuselage);
  const double startX = frameStation(fuselage, door, node.startFrameUID, "startFrameUID");
  const double endX = frameStation(fuselage, door, node.endFrameUID, "endFrameUID");
  const double fromX = std::min(startX, endX), toX = std::max(startX, endX);
  if (toX - fromX <= 1e-9 * std::max(1.0, std::abs(toX)))
    throw Error(ErrorCode::InvalidModel, "the door's start and end frames lie at one station", {},
                node.xpath + "/endFrameUID");
  const StringerPath first(fuselage,
                           stringerNamed(*door.structure, node.startStringerUID, node.xpath + "/startStringerUID"));
  const StringerPath last(fuselage,
                          stringerNamed(*door.structure, node.endStringerUID, node.xpath + "/endStringerUID"));

  std::vector<TopoDS_Face> split;
  if (auto direct =
          geometry::skinSplitByLoop(compoundOf(fuselage.skinFaces()), doorLoop(fuselage, first, last, fromX, toX),
                                    geometry::kTraceTolerance * fuselage.reach()))
    split = *direct;
  else
    split = splitByFramesAndStringers(fuselage, first, last, fromX, toX, node.xpath);
  std::vector<TopoDS_Face> pieces;
  for (const TopoDS_Face& face : split) {
    GProp_GProps area;
    BRepGProp::SurfaceProperties(face, area);
    const gp_Pnt centre = fuselage.toLocal(area.CentreOfMass());
    if (centre.X() > fromX && centre.X() < toX && betweenStringers(fuselage, first, last, centre, node.xpath))
      pieces.push_back(face);
  }
  NamedFaces shape;
  shape.add(uid + "/door", pieces);
  if (shape.empty())
    throw Error(ErrorCode::InvalidModel, "the door's frames and stringers enclose no part of the skin", {}, node.xpath);
  return shape.shape();
}

}  // namespace airshape::structure
