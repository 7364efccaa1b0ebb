#include "spar_web.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/faces_inside.h"
#include "airshape/geometry/ruled_face_between_skins.h"
#include "airshape/geometry/skin_section.h"
#include "device_section.h"
#include "named_faces.h"
#include "structure_frame.h"

namespace airshape::structure {

namespace {

/// A spar position's point on the chord surface and its component segment eta.
struct PlacedPosition {
  gp_Pnt point;
  double eta = 0.0;
};

PlacedPosition placed(const StructureFrame& frame, const SparPosition& position) {
  if (position.kind != SparPosition::Kind::EtaXsi) {
    const gp_Pnt point = frame.positionPoint(position);
    return {frame.toGlobal(point), frame.etaOf(point)};
  }
  try {
    return {frame.toGlobal(frame.chordPoint(position.referenceUid, position.eta, position.xsi)),
            frame.frameEta(position.referenceUid, position.eta)};
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, position.xpath + "/sparPositionEtaXsi");
  }
}

/// The plane face between the lines along `up` through two spar points, reaching `reach`
/// above and below them, carried `reach` beyond the inner or outer point where asked.
TopoDS_Face wallFace(const gp_Pnt& inner, const gp_Pnt& outer, bool beyondInner, bool beyondOuter, const gp_Vec& up,
                     double reach) {
  gp_Pnt innerPoint = inner, outerPoint = outer;
  const gp_Vec along = gp_Vec(inner, outer).Normalized();
  if (beyondInner) innerPoint.Translate(-reach * along);
  if (beyondOuter) outerPoint.Translate(reach * along);
  // Two parallel lines bound a plane face: the section of the skins by a plane is found much
  // faster than by a general ruled surface.
  BRepBuilderAPI_MakePolygon outline(innerPoint.Translated(reach * up), innerPoint.Translated(-reach * up),
                                     outerPoint.Translated(-reach * up), outerPoint.Translated(reach * up), true);
  return BRepBuilderAPI_MakeFace(outline.Wire(), true).Face();
}

/// The piece between two positions: a plane face, carried on where asked, or the ruled surface
/// between the lines along their different directions, with a plane piece of its own beyond a
/// carried end.
std::vector<SparWall::Piece> piecesBetween(const gp_Pnt& from, const gp_Pnt& to, const gp_Vec& fromUp,
                                           const gp_Vec& toUp, bool carriedBefore, bool carriedAfter, double reach) {
  SparWall::Piece piece{{}, from, to, fromUp, toUp, carriedBefore, carriedAfter};
  if (piece.plane()) {
    piece.face = wallFace(from, to, carriedBefore, carriedAfter, fromUp, reach);
    return {piece};
  }
  piece.carriedBefore = piece.carriedAfter = false;
  piece.face =
      geometry::ruledFace(geometry::straightLine(from.Translated(-reach * fromUp), from.Translated(reach * fromUp)),
                          geometry::straightLine(to.Translated(-reach * toUp), to.Translated(reach * toUp)));
  std::vector<SparWall::Piece> pieces;
  const gp_Vec along = gp_Vec(from, to).Normalized();
  if (carriedBefore) {
    const gp_Pnt before = from.Translated(-along);
    pieces.push_back({wallFace(before, from, true, false, fromUp, reach), before, from, fromUp, fromUp, true, false});
  }
  pieces.push_back(piece);
  if (carriedAfter) {
    const gp_Pnt after = to.Translated(along);
    pieces.push_back({wallFace(to, after, false, true, toUp, reach), to, after, toUp, toUp, false, true});
  }
  return pieces;
}

/// Whether a piece that carries a twisted piece's plane on beyond the wall's end (past the
/// component segment's root or tip) meets the skins only at that end: then it holds nothing.
bool beyondSkins(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin, const geometry::CrossingLines& lines,
                 const SparWall::Piece& piece, double tolerance) {
  if (piece.carriedBefore == piece.carriedAfter) return false;
  const double slack = tolerance / lines.along.Magnitude();
  for (const TopoDS_Shape* skin : {&upperSkin, &lowerSkin}) {
    const auto span = geometry::crossingSpan(*skin, lines, tolerance);
    if (!span) return false;
    const bool inside = piece.carriedBefore ? span->first < 1.0 - slack : span->second > slack;
    if (inside) return false;
  }
  return true;
}

}  // namespace

std::vector<TopoDS_Face> SparWall::faces() const {
  std::vector<TopoDS_Face> all;
  for (const Piece& piece : pieces) all.push_back(piece.face);
  return all;
}

SparWall sparWall(const StructureFrame& frame, const SparSegment& spar, SparWall::Ends ends) {
  if (spar.positions.size() < 2)
    throw Error(ErrorCode::InvalidModel, "a spar segment needs at least two spar positions", {},
                spar.xpath + "/sparPositionUIDs");
  std::vector<PlacedPosition> placedPositions;
  for (const SparPosition& position : spar.positions) placedPositions.push_back(placed(frame, position));
  const double reach = frame.reach();
  std::vector<gp_Vec> ups;
  for (const PlacedPosition& position : placedPositions)
    ups.push_back(frame.toGlobal(frame.uprightAtSparPosition(position.eta)).Normalized());
  const bool always = ends == SparWall::Ends::AlwaysCarried;
  SparWall wall;
  for (std::size_t i = 1; i < placedPositions.size(); ++i) {
    const PlacedPosition &inner = placedPositions[i - 1], &outer = placedPositions[i];
    if (inner.point.Distance(outer.point) < 1e-9)
      throw Error(ErrorCode::InvalidModel,
                  "spar positions '" + spar.positions[i - 1].uid + "' and '" + spar.positions[i].uid + "' coincide", {},
                  spar.xpath);
    const bool beyondInner = (always && i == 1) || inner.eta <= 1e-7;
    const bool beyondOuter = (always && i + 1 == placedPositions.size()) || outer.eta >= 1.0 - 1e-7;
    for (SparWall::Piece& piece :
         piecesBetween(inner.point, outer.point, ups[i - 1], ups[i], beyondInner, beyondOuter, reach))
      wall.pieces.push_back(std::move(piece));
  }
  for (const PlacedPosition& position : placedPositions) wall.points.push_back(position.point);
  return wall;
}

NamedShape sparWeb(const Configuration& configuration, const StructureServices& services, const SparSegment& spar) {
  const StructureFrame frame(configuration, services, spar.componentSegmentUid, spar.wingUid, spar.deviceUid);
  const SparWall wall = sparWall(frame, spar, SparWall::Ends::CarriedAtComponentSegmentEnds);
  // Each piece straight from the skins where they allow it (much faster than a Boolean cut of
  // skins with many knots); the others cut out of the component segment by one Boolean common.
  const TopoDS_Shape upperSkin = frame.skin(true), lowerSkin = frame.skin(false);
  const double tolerance = geometry::kTraceTolerance * frame.reach();
  // In a device cut out of its wing by a simple solid: the wing's section in common with the
  // solid's, in the piece's plane (device_section.h).
  std::optional<DeviceSection> inDevice;
  if (const std::optional<TopoDS_Shape> cutter = frame.deviceCutter()) inDevice.emplace(frame, *cutter);
  const auto traced = [&](std::size_t i) -> std::optional<std::vector<TopoDS_Face>> {
    const auto one = [](const std::optional<TopoDS_Face>& face) {
      return face ? std::optional<std::vector<TopoDS_Face>>({*face}) : std::nullopt;
    };
    const SparWall::Piece& piece = wall.pieces[i];
    if (!piece.plane()) {  // a twisted piece: the ruled surface between its lines
      if (frame.inDevice()) return std::nullopt;
      return one(geometry::ruledSectionBetweenSkins(upperSkin, lowerSkin,
                                                    {piece.from, piece.to, piece.fromUp, piece.toUp}, tolerance));
    }
    // The piece's plane: lines along up from one spar point (t = 0) to the next (t = 1).
    const geometry::CrossingLines lines{piece.from, gp_Vec(piece.from, piece.to), piece.fromUp};
    const geometry::CrossingEnd from =
        piece.carriedBefore ? geometry::CrossingEnd::open() : geometry::CrossingEnd::atLine(0.0);
    const geometry::CrossingEnd to =
        piece.carriedAfter ? geometry::CrossingEnd::open() : geometry::CrossingEnd::atLine(1.0);
    if (frame.inDevice())
      return inDevice ? inDevice->faces(lines, from, to, geometry::OpenEnds::ClosedStraight) : std::nullopt;
    if (beyondSkins(upperSkin, lowerSkin, lines, piece, tolerance)) return std::vector<TopoDS_Face>{};
    return one(geometry::sectionBetweenSkins(upperSkin, lowerSkin, lines, from, to, tolerance,
                                             geometry::OpenEnds::ClosedStraight));
  };
  std::vector<std::vector<TopoDS_Face>> pieces;
  try {
    pieces = geometry::facesInsideEach(
        wall.faces(), [&]() -> const TopoDS_Shape& { return frame.solid(); }, traced);
  } catch (const Error& error) {
    throw Error(error.code(), std::string("the spar cannot be cut out of ") + frame.hostName(), {}, spar.xpath);
  }
  NamedFaces web;
  for (const std::vector<TopoDS_Face>& inside : pieces) web.add(spar.uid + "/web", inside);
  if (web.empty())
    throw Error(ErrorCode::InvalidModel, std::string("the spar does not cross ") + frame.hostName(), {}, spar.xpath);
  return web.shape();
}

}  // namespace airshape::structure
