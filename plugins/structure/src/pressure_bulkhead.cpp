#include "pressure_bulkhead.h"

#include <algorithm>
#include <cmath>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeHalfSpace.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "compounds.h"
#include "faces_inside.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "named_faces.h"
#include "position_rays.h"
#include "ruled_section.h"
#include "skin_lines.h"
#include "skin_section.h"

namespace airshape::structure {

namespace {

/// The rays of a frame's positions at one station, as the frame runs through them: each
/// position's, and for a frame of two positions the ray halfway between them too (the frame
/// runs along the ruled surface between their rays, position_rays.h), which tells the side.
/// Each ray comes with the CPACS path an error about it names.
std::vector<std::pair<PositionRay, std::string>> raysAlong(const FuselageFrame& fuselage,
                                                           const schema::FrameType& frame) {
  std::vector<std::pair<PositionRay, std::string>> rays;
  for (const auto& position : frame.framePosition)
    rays.emplace_back(PositionRay::of(fuselage, position), position.xpath);
  if (rays.size() == 2) {
    const PositionRay middle = PositionRay::between(rays[0].first, rays[1].first, 0.5);
    if (middle.direction.Magnitude() < 1e-9)
      throw Error(ErrorCode::InvalidModel,
                  "the frame's two positions point opposite ways: the side its bulkhead lies on is not given", {},
                  frame.xpath);
    rays.insert(rays.begin() + 1, {middle, frame.xpath});
  }
  return rays;
}

/// The fuselage's cross section at a frame's station: the plane face inside the ring drawn on
/// the skin from the rays all round the frame's first position's reference point (skin_lines.h),
/// or, where the skin does not allow that, the plane's common with the fuselage's solid.
std::vector<TopoDS_Face> stationSection(const FuselageFrame& fuselage, const schema::FrameType& frame) {
  const gp_Pln station = fuselage.station(frame);
  if (const auto ring = raysOnSkin(fuselage, ringSpans(fuselage, frame))) {
    BRepBuilderAPI_MakeWire wire;
    for (const SkinEdge& piece : *ring) wire.Add(piece.edge);
    if (wire.IsDone() && wire.Wire().Closed()) {
      BRepBuilderAPI_MakeFace face(station, wire.Wire(), true);
      if (face.IsDone() && BRepCheck_Analyzer(face.Face()).IsValid()) return {face.Face()};
    }
  }
  return fuselage.crossSection(station.Location(), station.Axis().Direction());
}

/// The surface a riffled frame's rays sweep, inside the fuselage: each piece between two rays
/// from their origins out to the skin (ruled_section.h), or, where the skin does not allow
/// that, the swept surface's common with the fuselage's solid.
std::vector<TopoDS_Face> sweptInside(const FuselageFrame& fuselage, const schema::FrameType& frame) {
  const TopoDS_Shape skin = compoundOf(fuselage.skinFaces());
  std::vector<TopoDS_Face> faces;
  for (const auto& [a, b] : frameSpans(fuselage, frame)) {
    const gp_Pnt from = fuselage.toGlobal(a.origin), to = fuselage.toGlobal(b.origin);
    const geometry::RuledLines rays{from, to, gp_Vec(from, fuselage.toGlobal(a.origin.Translated(a.direction))),
                                    gp_Vec(to, fuselage.toGlobal(b.origin.Translated(b.direction))), true};
    const auto face = ruledFaceOutToSkin(skin, rays, kTraceTolerance * fuselage.reach());
    if (!face) return facesInside(compoundOf(frameSweep(fuselage, frame, fuselage.localReach())), fuselage.solid());
    faces.push_back(*face);
  }
  return faces;
}

/// A bulkhead on a frame of several positions at one station: each position's ray
/// (position_rays.h) meets the skin; the frame runs along the skin from the first of these points
/// to the last, and the bulkhead is the part of the cross section that the chord between them
/// cuts off on the side of the points in between.
std::vector<TopoDS_Face> sectionPart(const FuselageFrame& fuselage, const schema::FrameType& frame) {
  std::vector<gp_Pnt> hits;
  for (const auto& [ray, where] : raysAlong(fuselage, frame))
    hits.push_back(fuselage.skinAhead(fuselage.toGlobal(ray.origin), fuselage.toGlobal(gp_Dir(ray.direction)), where));
  const gp_Dir normal = fuselage.toGlobal(gp_Dir(1, 0, 0));
  const gp_Vec chord(hits.front(), hits.back());
  if (chord.Magnitude() < 1e-9 || chord.Crossed(gp_Vec(normal)).Magnitude() < 1e-12)
    throw Error(ErrorCode::InvalidModel, "the frame's first and last positions meet the skin at one point", {},
                frame.xpath);
  const TopoDS_Face cut = BRepBuilderAPI_MakeFace(gp_Pln(hits.front(), gp_Dir(chord.Crossed(gp_Vec(normal)))));
  const TopoDS_Shape side = BRepPrimAPI_MakeHalfSpace(cut, hits[1]).Solid();
  return facesInside(compoundOf(stationSection(fuselage, frame)), side);
}

}  // namespace

NamedShape pressureBulkhead(const Configuration& configuration, const std::string& uid) {
  const auto bulkhead = pressureBulkheadNamed(configuration, uid);
  const schema::FrameType& frame =
      frameNamed(*bulkhead.structure, bulkhead.node->frameUID, bulkhead.node->xpath + "/frameUID");
  const FuselageFrame fuselage(configuration, *bulkhead.fuselage);
  std::vector<TopoDS_Face> faces;
  try {
    if (fuselage.offFirstStation(frame) != nullptr) {
      faces = sweptInside(fuselage, frame);
    } else if (frame.framePosition.size() > 1) {
      faces = sectionPart(fuselage, frame);
    } else {
      faces = stationSection(fuselage, frame);
    }
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(ErrorCode::InvalidModel, "the fuselage cannot be cut at the bulkhead's frame", {}, frame.xpath);
  }
  NamedFaces shape;
  shape.add(uid + "/bulkhead", faces);
  if (shape.empty())
    throw Error(ErrorCode::InvalidModel, "the bulkhead's frame lies outside the fuselage", {}, frame.xpath);
  return shape.shape();
}

}  // namespace airshape::structure
