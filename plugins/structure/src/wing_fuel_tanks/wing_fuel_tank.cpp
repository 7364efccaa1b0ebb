#include "wing_fuel_tank.h"

#include <algorithm>

#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "named_faces.h"
#include "rib_faces.h"
#include "rib_list.h"
#include "spar_web.h"
#include "structure_frame.h"
#include "tank_from_skins.h"
#include "tank_outline.h"

namespace airshape::structure {

namespace {

/// A border of the tank: its wall across the component segment's solid (global frame) and its
/// line seen from above (wing frame).
struct Border {
  NamedShape wall;
  TankOutline::Border outline;
  TankWall direct;
};

/// Rethrows an error of a border's element with the border's CPACS path.
[[noreturn]] void rethrowAt(const Error& error, const std::string& what, const std::string& xpath) {
  throw Error(error.code(), what + ": " + error.message(), {}, xpath);
}

Border sparBorder(const Configuration& configuration, const StructureFrame& frame, const WingFuelTank& tank,
                  const std::string& sparUid, const std::string& xpath) {
  SparSegment spar;
  SparWall wall;
  try {
    spar = sparSegmentNamed(configuration, sparUid);
    if (spar.componentSegmentUid != tank.componentSegmentUid)
      throw Error(ErrorCode::InvalidModel, "it lies in component segment '" + spar.componentSegmentUid + "'");
    wall = sparWall(frame, spar, SparWall::Ends::AlwaysCarried);
  } catch (const Error& error) {
    rethrowAt(error, "the spar '" + sparUid + "' cannot bound the tank", xpath + "/sparUID");
  }
  Border border;
  NamedFaces faces;
  faces.add(tank.uid + "/" + sparUid, wall.faces());
  border.wall = faces.shape();
  border.direct.name = sparUid;
  border.direct.spar = true;
  if (wall.pieces.size() + 1 == wall.points.size()) {  // no plane pieces carried beyond twisted ones
    border.direct.points = wall.points;
    border.direct.ups.push_back(wall.pieces.front().fromUp);
    for (const SparWall::Piece& piece : wall.pieces) border.direct.ups.push_back(piece.toUp);
  }
  border.outline.spar = true;
  border.outline.firstEta = frame.etaOf(frame.toWing(wall.points.front()));
  border.outline.lastEta = frame.etaOf(frame.toWing(wall.points.back()));
  // Seen from above the wall follows its points, carried as far beyond its ends as the faces.
  std::vector<gp_Pnt>& line = border.outline.line;
  for (const gp_Pnt& point : wall.points) line.push_back(frame.toWing(point));
  const double reach = frame.reach();
  const double firstLength = line[0].Distance(line[1]), lastLength = line[line.size() - 2].Distance(line.back());
  line.front().Translate(reach / firstLength * gp_Vec(line[1], line[0]));
  line.back().Translate(reach / lastLength * gp_Vec(line[line.size() - 2], line.back()));
  border.outline.elementFrom = reach / (reach + firstLength);
  border.outline.elementTo = static_cast<double>(line.size() - 2) + lastLength / (lastLength + reach);
  return border;
}

Border ribBorder(const Configuration& configuration, const StructureFrame& frame, const WingFuelTank& tank,
                 const std::string& ribsUid, long long number, const std::string& xpath) {
  RibPlacement rib;
  try {
    const RibsDefinition ribs = ribsDefinitionNamed(configuration, ribsUid);
    if (ribs.componentSegmentUid != tank.componentSegmentUid)
      throw Error(ErrorCode::InvalidModel, "it lies in component segment '" + ribs.componentSegmentUid + "'");
    rib = ribPlacement(configuration, ribs, frame, number);
  } catch (const Error& error) {
    rethrowAt(error, "the ribs '" + ribsUid + "' cannot bound the tank", xpath);
  }
  // The wall is the rib's plane, across the whole solid; seen from above, where the plane
  // meets the level of the rib's point.
  const gp_Vec normal = rib.direction.Crossed(rib.up);
  const gp_Vec along = normal.Crossed(gp_Vec(0, 0, 1));
  if (normal.Magnitude() < 1e-9 || along.Magnitude() < 1e-9)
    throw Error(ErrorCode::InvalidModel, "the rib lies flat, so it bounds nothing seen from above", {},
                xpath + "/ribNumber");
  const double reach = frame.reach();
  const gp_Pln plane(frame.toGlobal(rib.point), gp_Dir(frame.toGlobal(normal)));
  Border border;
  NamedFaces faces;
  faces.add(tank.uid + "/" + ribsUid + "/rib " + std::to_string(number),
            {BRepBuilderAPI_MakeFace(plane, -reach, reach, -reach, reach).Face()});
  border.wall = faces.shape();
  border.direct.name = ribsUid + "/rib " + std::to_string(number);
  border.direct.point = frame.toGlobal(rib.point);
  border.direct.normal = frame.toGlobal(normal).Normalized();
  border.direct.up = frame.toGlobal(rib.up);
  const gp_Vec carried = reach * along.Normalized();
  border.outline.line = {rib.point.Translated(-carried), rib.point.Translated(carried)};
  return border;
}

std::vector<Border> bordersOf(const Configuration& configuration, const StructureFrame& frame,
                              const WingFuelTank& tank) {
  if (!tank.node->geometry) throw NoShape("the tank has no geometry (no borders): no shape", tank.xpath);
  std::vector<Border> borders;
  for (const auto& border : tank.node->geometry->border) {
    if (border.sparUID)
      borders.push_back(sparBorder(configuration, frame, tank, *border.sparUID, border.xpath));
    else if (border.ribDefinitionUID && border.ribNumber)
      borders.push_back(
          ribBorder(configuration, frame, tank, *border.ribDefinitionUID, *border.ribNumber, border.xpath));
    else
      throw Error(ErrorCode::InvalidModel, "a border names neither a spar nor a rib", {}, border.xpath);
  }
  return borders;
}

/// One solid of the cells chosen: the faces that bound only one of them (a face two cells
/// share lies inside), which share their edges already, as the splitter made them.
TopoDS_Solid unionOfCells(const std::vector<TopoDS_Shape>& cells) {
  TopTools_DataMapOfShapeInteger uses;
  for (const TopoDS_Shape& cell : cells)
    for (TopExp_Explorer face(cell, TopAbs_FACE); face.More(); face.Next()) {
      if (!uses.IsBound(face.Current())) uses.Bind(face.Current(), 0);
      uses.ChangeFind(face.Current()) += 1;
    }
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (const TopoDS_Shape& cell : cells)
    for (TopExp_Explorer face(cell, TopAbs_FACE); face.More(); face.Next())
      if (uses.Find(face.Current()) == 1) builder.Add(shell, face.Current());
  shell.Closed(true);
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  BRepLib::OrientClosedSolid(solid);
  return solid;
}

}  // namespace

NamedShape wingFuelTankSolid(const Configuration& configuration, const StructureServices& services,
                             const WingFuelTank& tank) {
  const StructureFrame frame(configuration, services, tank.componentSegmentUid, tank.wingUid, "");
  const std::vector<Border> borders = bordersOf(configuration, frame, tank);
  std::vector<TankOutline::Border> lines;
  std::vector<TankWall> walls;
  for (const Border& border : borders) {
    lines.push_back(border.outline);
    walls.push_back(border.direct);
  }
  const std::vector<std::size_t> order = TankOutline::orderAround(lines);
  if (!order.empty() && !std::is_sorted(order.begin(), order.end())) {
    std::string taken;
    for (const std::size_t index : order) taken += (taken.empty() ? "" : ", ") + std::to_string(index + 1);
    configuration.warnAboutGeometry({Problem::Severity::Warning, tank.xpath + "/geometry",
                                     "the borders are not listed in order around the tank; taken as border " + taken});
    std::vector<TankOutline::Border> ordered;
    std::vector<TankWall> orderedWalls;
    for (const std::size_t index : order) {
      ordered.push_back(lines[index]);
      orderedWalls.push_back(walls[index]);
    }
    lines = ordered;
    walls = orderedWalls;
  }
  std::optional<TankOutline> outline;
  try {
    outline.emplace(lines, [&frame](const gp_Pnt& point) { return frame.etaOf(point); });
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, tank.xpath + "/geometry");
  }
  // Straight from the skins where they allow it.
  const auto inOutline = [&](const gp_Pnt& point) { return outline->contains(frame.toWing(point)); };
  if (auto direct = tankFromSkins(frame, walls, inOutline, tank.uid)) return *direct;

  // Split the component segment's solid by every wall; the tank is the cells inside the outline.
  const NamedShape& componentSegment = configuration.shapes().namedShapeOf(configuration, tank.componentSegmentUid);
  TopTools_ListOfShape arguments, tools;
  arguments.Append(componentSegment.shape);
  std::vector<const NamedShape*> inputs = {&componentSegment};
  for (const Border& border : borders) {
    tools.Append(border.wall.shape);
    inputs.push_back(&border.wall);
  }
  BRepAlgoAPI_Splitter splitter;
  splitter.SetArguments(arguments);
  splitter.SetTools(tools);
  splitter.SetRunParallel(true);
  splitter.SetNonDestructive(true);  // the component segment's solid is shared, cached geometry
  splitter.Build();
  if (!splitter.IsDone() || splitter.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the tank cannot be cut out of its component segment", {}, tank.xpath);
  const NamedShape split = namedBooleanResult(splitter, inputs);

  std::vector<TopoDS_Shape> cells;
  for (TopExp_Explorer cell(split.shape, TopAbs_SOLID); cell.More(); cell.Next()) {
    GProp_GProps volume;
    BRepGProp::VolumeProperties(cell.Current(), volume);
    if (outline->contains(frame.toWing(volume.CentreOfMass()))) cells.push_back(cell.Current());
  }
  if (cells.empty())
    throw Error(ErrorCode::InvalidModel, "the borders enclose no part of the component segment", {},
                tank.xpath + "/geometry");

  NamedShape result{unionOfCells(cells), {}};
  const std::string prefix = tank.uid + "/";
  for (TopExp_Explorer face(result.shape, TopAbs_FACE); face.More(); face.Next())
    for (const auto& [name, named] : split.faces)
      if (named.IsSame(face.Current())) {
        result.faces.emplace_back(name.rfind(prefix, 0) == 0 ? name : prefix + name, TopoDS::Face(face.Current()));
        break;
      }
  return result;
}

}  // namespace airshape::structure
