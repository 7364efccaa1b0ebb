#include "tank_from_skins.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/ruled_face_between_skins.h"
#include "airshape/geometry/skin_section.h"
#include "airshape/geometry/skin_split.h"
#include "structure_frame.h"

namespace airshape::structure {

namespace {

/// Where two consecutive walls meet: a line (a point of it and its direction, pointing up), and
/// how far along each wall it lies (for a spar: piece index plus share; 0 for a rib).
struct Corner {
  gp_Pnt point;
  gp_Vec direction;
  double alongFirst = 0.0, alongSecond = 0.0;
};

/// The line where a spar's wall meets a rib's plane: on the spar piece the plane crosses (the
/// first and last piece carried on); nothing where it crosses none or a twisted one.
std::optional<Corner> sparMeetsRib(const TankWall& spar, const TankWall& rib, bool sparFirst) {
  const std::size_t pieces = spar.points.size() - 1;
  for (std::size_t k = 0; k < pieces; ++k) {
    const gp_Vec along(spar.points[k], spar.points[k + 1]);
    const double across = along.Dot(rib.normal);
    if (std::abs(across) < 1e-12 * along.Magnitude()) continue;
    const double t = gp_Vec(spar.points[k], rib.point).Dot(rib.normal) / across;
    if ((t < 0.0 && k > 0) || (t > 1.0 && k + 1 < pieces)) continue;
    if (!spar.ups[k].IsParallel(spar.ups[k + 1], 1e-12)) return std::nullopt;  // a twisted piece
    gp_Vec direction = along.Crossed(spar.ups[k]).Crossed(rib.normal);
    if (direction.Magnitude() < 1e-12) return std::nullopt;
    if (direction.Dot(spar.ups[k]) < 0.0) direction.Reverse();
    const double position = static_cast<double>(k) + t;
    Corner corner{spar.points[k].Translated(t * along), direction.Normalized(), 0.0, 0.0};
    (sparFirst ? corner.alongFirst : corner.alongSecond) = position;
    return corner;
  }
  return std::nullopt;
}

/// The line where two rib planes meet.
std::optional<Corner> ribMeetsRib(const TankWall& a, const TankWall& b) {
  gp_Vec direction = a.normal.Crossed(b.normal);
  if (direction.Magnitude() < 1e-12) return std::nullopt;
  if (direction.Dot(a.up) < 0.0) direction.Reverse();
  const double da = gp_Vec(a.point.XYZ()).Dot(a.normal), db = gp_Vec(b.point.XYZ()).Dot(b.normal);
  const gp_Vec point = (da * b.normal - db * a.normal).Crossed(a.normal.Crossed(b.normal)) /
                       a.normal.Crossed(b.normal).SquareMagnitude();
  return Corner{gp_Pnt(point.XYZ()), direction.Normalized(), 0.0, 0.0};
}

/// Where two spars meet: at a position both have.
std::optional<Corner> sparMeetsSpar(const TankWall& a, const TankWall& b, double tolerance) {
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (std::size_t j = 0; j < b.points.size(); ++j)
      if (a.points[i].Distance(b.points[j]) <= tolerance)
        return Corner{a.points[i], a.ups[i], static_cast<double>(i), static_cast<double>(j)};
  return std::nullopt;
}

std::optional<Corner> meet(const TankWall& a, const TankWall& b, double tolerance) {
  if (a.spar && b.spar) return sparMeetsSpar(a, b, tolerance);
  if (a.spar) return sparMeetsRib(a, b, true);
  if (b.spar) return sparMeetsRib(b, a, false);
  return ribMeetsRib(a, b);
}

/// The loop around the tank and, for each of its sides, the wall it lies in.
struct Loop {
  geometry::RuledLoop lines;
  std::vector<std::size_t> sideWalls;
};

/// The plane of the component segment's inner (eta 0) or outer (eta 1) end as a wall: the
/// section's plane there, up along its thickness.
TankWall endWall(const StructureFrame& frame, bool inner) {
  const double eta = inner ? 0.0 : 1.0;
  const gp_Pnt front = frame.chordPoint("", eta, 0.0), back = frame.chordPoint("", eta, 1.0);
  const gp_Vec up = frame.thicknessDirection(eta, 0.5);
  TankWall wall;
  wall.name = frame.componentSegmentUid() + (inner ? "/inner end" : "/outer end");
  wall.point = frame.toGlobal(front);
  wall.normal = frame.toGlobal(gp_Vec(front, back).Crossed(up)).Normalized();
  wall.up = frame.toGlobal(up).Normalized();
  return wall;
}

/// The walls closed: where the last and the first are spars that do not meet, the component
/// segment's end nearer to the other corners (their mean eta below or above 0.5) joins them, as
/// the tank's outline is closed (tank_outline.h).
std::vector<TankWall> closed(const StructureFrame& frame, std::vector<TankWall> walls, double tolerance) {
  const std::size_t n = walls.size();
  if (!walls.back().spar || !walls.front().spar || meet(walls.back(), walls.front(), tolerance)) return walls;
  double meanEta = 0.0;
  std::size_t corners = 0;
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (const auto corner = meet(walls[i], walls[i + 1], tolerance)) {
      meanEta += frame.etaOf(frame.toWing(corner->point));
      ++corners;
    }
  if (corners == 0) return walls;
  walls.push_back(endWall(frame, meanEta / static_cast<double>(corners) < 0.5));
  return walls;
}

/// Whether the sewn solid holds every face and its shell is closed: every edge shared by two
/// faces. (OCCT's whole check of the solid would classify every face's wires again, a fifth of
/// the tank's time.)
bool closesAll(const TopoDS_Shape& solid, std::size_t faces) {
  TopExp_Explorer shell(solid, TopAbs_SHELL);
  if (!shell.More() || !BRep_Tool::IsClosed(shell.Current())) return false;
  std::size_t held = 0;
  for (TopExp_Explorer face(solid, TopAbs_FACE); face.More(); face.Next()) ++held;
  return held == faces;
}

std::optional<Loop> loopAround(const std::vector<TankWall>& walls, double tolerance) {
  const std::size_t n = walls.size();
  std::vector<Corner> corners;  // corners[i]: wall i meets wall i + 1
  for (std::size_t i = 0; i < n; ++i) {
    const auto corner = meet(walls[i], walls[(i + 1) % n], tolerance);
    if (!corner) return std::nullopt;
    corners.push_back(*corner);
  }
  Loop loop;
  for (std::size_t i = 0; i < n; ++i) {
    // Wall i runs from where the previous wall meets it to where it meets the next.
    const Corner& start = corners[(i + n - 1) % n];
    loop.lines.points.push_back(start.point);
    loop.lines.directions.push_back(start.direction);
    loop.sideWalls.push_back(i);
    if (!walls[i].spar) continue;
    const double from = start.alongSecond, to = corners[i].alongFirst;
    // The spar's positions between, in the order the wall runs.
    std::vector<std::size_t> between;
    for (std::size_t k = 0; k < walls[i].points.size(); ++k)
      if (static_cast<double>(k) > std::min(from, to) + 1e-9 && static_cast<double>(k) < std::max(from, to) - 1e-9)
        between.push_back(k);
    if (from > to) std::reverse(between.begin(), between.end());
    for (const std::size_t k : between) {
      loop.lines.points.push_back(walls[i].points[k]);
      loop.lines.directions.push_back(walls[i].ups[k]);
      loop.sideWalls.push_back(i);
    }
  }
  return loop;
}

}  // namespace

std::optional<NamedShape> tankFromSkins(const StructureFrame& frame, const std::vector<TankWall>& walls,
                                        const std::function<bool(const gp_Pnt&)>& inside, const std::string& tankUid) {
  const double reach = frame.reach(), tolerance = geometry::kTraceTolerance * reach;
  const std::vector<TankWall> all = closed(frame, walls, 1e-9 * reach);
  auto loop = loopAround(all, 1e-9 * reach);
  if (!loop) return std::nullopt;
  const TopoDS_Shape upperSkin = frame.skin(true), lowerSkin = frame.skin(false);
  const auto upper = geometry::skinPiecesWhere(upperSkin, loop->lines, inside, tolerance);
  const auto lower = geometry::skinPiecesWhere(lowerSkin, loop->lines, inside, tolerance);
  if (!upper || !lower || upper->empty() || lower->empty()) return std::nullopt;

  std::vector<TopoDS_Face> faces;
  std::vector<std::string> names;
  const std::string skinName = tankUid + "/" + frame.componentSegmentUid();
  for (const TopoDS_Face& face : *upper) faces.push_back(face), names.push_back(skinName + "/upper");
  for (const TopoDS_Face& face : *lower) faces.push_back(face), names.push_back(skinName + "/lower");
  const std::size_t n = loop->lines.points.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    const geometry::RuledLines side{loop->lines.points[k], loop->lines.points[next], loop->lines.directions[k],
                                    loop->lines.directions[next]};
    const auto face = geometry::ruledSectionBetweenSkins(upperSkin, lowerSkin, side, tolerance);
    if (!face) return std::nullopt;
    faces.push_back(*face);
    names.push_back(tankUid + "/" + all[loop->sideWalls[k]].name);
  }
  // Sewn as tightly as the pieces allow: a wall along a skin's edge (a rib in the root) follows
  // that edge less closely than a crossing in the skin's middle.
  for (const double join : {10.0 * tolerance, 100.0 * tolerance}) {
    try {
      std::vector<TopoDS_Face> sewn;
      NamedShape tank{geometry::sewnSolid(faces, &sewn, join, geometry::Orienting::ByClassification), {}};
      if (!closesAll(tank.shape, faces.size())) continue;  // pieces that did not close
      for (std::size_t k = 0; k < sewn.size(); ++k)
        if (!sewn[k].IsNull()) tank.faces.emplace_back(names[k], sewn[k]);
      return tank;
    } catch (const Error&) {
    } catch (const Standard_Failure&) {
    }
  }
  return std::nullopt;
}

}  // namespace airshape::structure
