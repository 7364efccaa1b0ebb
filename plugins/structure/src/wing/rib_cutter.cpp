#include "rib_cutter.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/faces_inside.h"
#include "airshape/geometry/plane_region.h"
#include "airshape/geometry/section_profile.h"
#include "airshape/geometry/skin_section.h"
#include "airshape/model/placement.h"
#include "device_section.h"
#include "spar_list.h"
#include "spar_web.h"

namespace airshape::structure {

bool sameName(const std::string& a, const char* b) {
  const std::string other(b);
  return a.size() == other.size() && std::equal(a.begin(), a.end(), other.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool isLeadingEdge(const std::string& name) { return sameName(name, "leadingEdge") || sameName(name, "le"); }

bool isWingEdge(const std::string& name) {
  return isLeadingEdge(name) || sameName(name, "trailingEdge") || sameName(name, "te");
}

RibCutter::RibCutter(const Configuration& configuration, const StructureFrame& frame,
                     const schema::WingComponentSegmentStructureType& structure)
    : configuration_(configuration), frame_(frame), structure_(structure), reach_(frame.reach()) {}

gp_Pnt RibCutter::pointOf(const schema::Child<schema::EtaXsiPointType>& etaXsi,
                          const schema::Child<schema::CurvePointType>& curve,
                          const std::optional<std::string>& sparPosition, const std::string& where) const {
  if (etaXsi)
    return frame_.chordPoint(etaXsi->referenceUID, model::fraction(etaXsi->eta, where + "EtaXsiPoint/eta"),
                             model::fraction(etaXsi->xsi, where + "EtaXsiPoint/xsi"));
  if (curve)
    return frame_.lineNamed(curve->referenceUID, where + "CurvePoint")
        .at(model::fraction(curve->eta, where + "CurvePoint/eta"));
  if (sparPosition) {
    if (structure_.spars && structure_.spars->sparPositions)
      for (const auto& position : structure_.spars->sparPositions->sparPosition)
        if (position.uID == *sparPosition) return frame_.positionPoint(sparPositionOf(configuration_, position));
    throw Error(ErrorCode::InvalidModel, "spar position '" + *sparPosition + "' names no spar position", {},
                where + "SparPositionUID");
  }
  throw Error(ErrorCode::InvalidModel, "the rib has no start or end point", {}, where);
}

std::vector<gp_Pnt> RibCutter::sparSection(const std::string& spar, const gp_Pln& plane,
                                           const std::string& where) const {
  // The spar's web stands in its wall, a plane piece between each two of its positions
  // (spar_web.cpp): where the plane meets it is a straight line, found without cutting the web
  // (a Boolean section of the web cost 20 ms a rib).
  auto known = walls_.find(spar);
  if (known == walls_.end()) {
    try {
      known = walls_
                  .emplace(spar, sparWall(frame_, sparSegmentNamed(configuration_, spar),
                                          SparWall::Ends::CarriedAtComponentSegmentEnds))
                  .first;
    } catch (const Error& error) {
      throw Error(error.code(), "spar '" + spar + "': " + error.message(), {}, where);
    }
  }
  const gp_Vec normal(plane.Axis().Direction());
  for (const SparWall::Piece& wallPiece : known->second.pieces) {
    const gp_Vec piece(wallPiece.from, wallPiece.to);
    const double across = piece.Dot(normal);
    if (std::abs(across) < 1e-12 * piece.Magnitude()) continue;  // the piece runs along the plane
    const double t = gp_Vec(wallPiece.from, plane.Location()).Dot(normal) / across;
    if ((t < -1e-9 && !wallPiece.carriedBefore) || (t > 1.0 + 1e-9 && !wallPiece.carriedAfter)) continue;
    const gp_Pnt crossing = wallPiece.from.Translated(t * piece);
    // On a twisted piece, the wall's line at the crossing (a ruling of the ruled surface).
    const gp_Vec up = wallPiece.upAt(std::clamp(t, 0.0, 1.0));
    gp_Vec along = normal.Crossed(piece.Crossed(up));
    if (along.Magnitude() < 1e-12) continue;
    along.Normalize();
    if (along.Dot(up) < 0.0) along.Reverse();
    return {crossing.Translated(-reach_ * along), crossing.Translated(reach_ * along)};
  }
  throw Error(ErrorCode::InvalidModel, "a rib does not meet spar '" + spar + "'", {}, where);
}

const std::pair<TopoDS_Shape, TopoDS_Shape>& RibCutter::skins() const {
  if (!skins_) skins_.emplace(frame_.skin(true), frame_.skin(false));
  return *skins_;
}

std::vector<gp_Pnt> RibCutter::side(const std::string& border, const gp_Pnt& origin, const gp_Vec& outwards,
                                    const gp_Vec& up, const gp_Pln& plane, const std::string& where) const {
  const gp_Vec globalUp = frame_.toGlobal(up).Normalized();
  if (isWingEdge(border)) {
    const gp_Pnt far = frame_.toGlobal(origin.Translated(reach_ * outwards));
    return {far.Translated(-reach_ * globalUp), far.Translated(reach_ * globalUp)};
  }
  std::vector<gp_Pnt> points = sparSection(border, plane, where);
  std::sort(points.begin(), points.end(), [&](const gp_Pnt& a, const gp_Pnt& b) {
    return gp_Vec(a.XYZ()).Dot(globalUp) < gp_Vec(b.XYZ()).Dot(globalUp);
  });
  points.erase(
      std::unique(points.begin(), points.end(), [](const gp_Pnt& a, const gp_Pnt& b) { return a.Distance(b) < 1e-9; }),
      points.end());
  points.insert(points.begin(), points.front().Translated(-reach_ * globalUp));
  points.push_back(points.back().Translated(reach_ * globalUp));
  return points;
}

geometry::CrossingEnd RibCutter::border(const std::string& name, const gp_Pln& plane, const std::string& where) const {
  if (isWingEdge(name)) return geometry::CrossingEnd::open();           // the rib runs on to where the skins meet
  const std::vector<gp_Pnt> section = sparSection(name, plane, where);  // symmetric about the spar's line
  return geometry::CrossingEnd::atBorder(gp_Pnt((section.front().XYZ() + section.back().XYZ()) / 2.0),
                                         gp_Vec(section.front(), section.back()));
}

RibOutline RibCutter::outline(const gp_Pnt& point, const gp_Vec& direction, const gp_Vec& up,
                              const std::string& ribStart, const std::string& ribEnd, const std::string& name,
                              const std::string& where) const {
  const gp_Vec normal = frame_.toGlobal(direction).Crossed(frame_.toGlobal(up));
  const gp_Pln plane(frame_.toGlobal(point), gp_Dir(normal));
  const std::vector<gp_Pnt> front = side(ribStart, point, -direction, up, plane, where + "/ribStart");
  const std::vector<gp_Pnt> back = side(ribEnd, point, direction, up, plane, where + "/ribEnd");
  BRepBuilderAPI_MakePolygon polygon;
  for (const gp_Pnt& p : front) polygon.Add(p);
  for (auto p = back.rbegin(); p != back.rend(); ++p) polygon.Add(*p);
  polygon.Close();
  BRepBuilderAPI_MakeFace face(plane, polygon.Wire(), true);
  if (!face.IsDone()) throw Error(ErrorCode::InvalidModel, "the outline of " + name + " is not plane", {}, where);
  RibOutline outline{face.Face(),
                     geometry::CrossingLines{frame_.toGlobal(point), frame_.toGlobal(direction), frame_.toGlobal(up)},
                     border(ribStart, plane, where + "/ribStart"), border(ribEnd, plane, where + "/ribEnd")};
  return outline;
}

std::vector<std::vector<TopoDS_Face>> RibCutter::cutAll(const std::vector<RibOutline>& outlines,
                                                        const std::vector<std::string>& names,
                                                        const std::string& where) const {
  // Ribs straight from the skins where they allow it (much faster than a Boolean cut of skins
  // with many knots); the others cut out of the component segment (or device) by one common.
  // In a device cut out of its wing by a simple solid: the wing's section in common with the
  // solid's, in the rib's plane (device_section.h).
  std::optional<DeviceSection> inDevice;
  if (const std::optional<TopoDS_Shape> cutter = frame_.deviceCutter()) inDevice.emplace(frame_, *cutter);
  const auto direct = [&](std::size_t i) -> std::optional<std::vector<TopoDS_Face>> {
    if (!frame_.inDevice()) {
      const auto& [upper, lower] = skins();
      if (auto face = sectionOf(outlines[i], upper, lower)) return std::vector<TopoDS_Face>{*face};
      return inSection(outlines[i], upper, lower);
    }
    if (!inDevice) return std::nullopt;
    const RibOutline& outline = outlines[i];
    return inDevice->faces(outline.lines, outline.start, outline.end, geometry::OpenEnds::SkinsMeet);
  };
  std::vector<TopoDS_Face> faces;
  for (const RibOutline& outline : outlines) faces.push_back(outline.face);
  std::vector<std::vector<TopoDS_Face>> ribs;
  try {
    ribs = geometry::facesInsideEach(
        faces, [&]() -> const TopoDS_Shape& { return frame_.solid(); }, direct);
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, std::string("the ribs cannot be cut out of ") + frame_.hostName(), {}, where);
  }
  // A rib of a set that does not cross (a rib at the root turned so that it runs inboard of it)
  // is left out with a warning; the set's other ribs are built. A set none of whose ribs
  // crosses is an error.
  std::vector<std::string> missing;
  for (std::size_t i = 0; i < ribs.size(); ++i)
    if (ribs[i].empty()) missing.push_back(names[i]);
  if (missing.size() == ribs.size()) {
    if (ribs.size() == 1)
      throw Error(ErrorCode::InvalidModel, names[0] + " does not cross " + frame_.hostName(), {}, where);
    throw Error(ErrorCode::InvalidModel,
                "none of its " + std::to_string(ribs.size()) + " ribs crosses " + frame_.hostName(), {}, where);
  }
  for (const std::string& name : missing) warnLeftOut(where, name + " does not cross " + frame_.hostName());
  return ribs;
}

void RibCutter::warnLeftOut(const std::string& where, const std::string& why) const {
  configuration_.warnAboutGeometry(
      {Problem::Severity::Warning, where, why + "; left out, the set's other ribs are built"});
}

std::optional<TopoDS_Face> RibCutter::sectionOf(const RibOutline& outline, const TopoDS_Shape& upper,
                                                const TopoDS_Shape& lower) const {
  return geometry::sectionBetweenSkins(upper, lower, outline.lines, outline.start, outline.end,
                                       geometry::kTraceTolerance * reach_, geometry::OpenEnds::SkinsMeet);
}

std::optional<std::vector<TopoDS_Face>> RibCutter::inSection(const RibOutline& outline, const TopoDS_Shape& upper,
                                                             const TopoDS_Shape& lower) const {
  // The trace fails where the rib's plane runs along the skins' patch boundaries: a rib lying
  // in the root, the tip or a section between segments is the profile there, between its
  // borders (the outline's sides).
  const double tolerance = geometry::kTraceTolerance * reach_;
  const gp_Pln plane(outline.lines.origin, outline.lines.planeNormal());
  const std::optional<geometry::PlaneRegion> profile = geometry::profileInPlane(upper, lower, plane, 10.0 * tolerance);
  if (!profile) return std::nullopt;
  const std::optional<geometry::PlaneRegion> between = geometry::regionOf(plane, outline.face);
  if (!between) return std::nullopt;
  std::optional<std::vector<TopoDS_Face>> faces = geometry::commonOf(plane, *profile, *between, tolerance);
  if (!faces || faces->empty()) return std::nullopt;
  return faces;
}

std::vector<TopoDS_Face> RibCutter::cut(const gp_Pnt& point, const gp_Vec& direction, const gp_Vec& up,
                                        const std::string& ribStart, const std::string& ribEnd, const std::string& name,
                                        const std::string& where) const {
  return cutAll({outline(point, direction, up, ribStart, ribEnd, name, where)}, {name}, where).front();
}

}  // namespace airshape::structure
