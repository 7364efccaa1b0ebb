#include "pressure_bulkhead.h"

#include <algorithm>
#include <cmath>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeHalfSpace.hxx>
#include <BRep_Tool.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/faces_inside.h"
#include "airshape/geometry/plane_face_within.h"
#include "airshape/geometry/skin_section.h"
#include "compounds.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "named_faces.h"
#include "position_rays.h"
#include "skin_lines.h"

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

/// A bulkhead on a riffled frame (positions at several stations), as the reference library makes
/// it (the schema does not say): a plane face at the mean station of the frame's reference points,
/// bounded by the frame's line (riffledFrameSpans), closed by a straight edge where the line does
/// not come back to its start. The line leaves the plane by up to half the riffle's depth: the face
/// is the part of the plane inside the line seen along x, each edge keeping its course
/// (geometry::planeFaceWithin).
TopoDS_Face planeWithinRiffledFrame(const Configuration& configuration, const FuselageFrame& fuselage,
                                    const schema::FrameType& frame) {
  Handle(TopTools_HSequenceOfShape) edges = new TopTools_HSequenceOfShape;
  for (const SkinEdge& piece : frameOnSkin(configuration, nullptr, frame.uID)) edges->Append(piece.edge);
  Handle(TopTools_HSequenceOfShape) wires;
  ShapeAnalysis_FreeBounds::ConnectEdgesToWires(edges, geometry::kTraceTolerance * fuselage.reach() * 10.0, false,
                                                wires);
  if (wires.IsNull() || wires->Length() != 1)
    throw Error(ErrorCode::InvalidModel, "the riffled frame's line is not one line", {}, frame.xpath);
  TopoDS_Wire line = TopoDS::Wire(wires->Value(1));
  if (!BRep_Tool::IsClosed(line)) {
    TopoDS_Vertex first, last;
    TopExp::Vertices(line, first, last);
    BRepBuilderAPI_MakeWire closed(line);
    closed.Add(BRepBuilderAPI_MakeEdge(last, first).Edge());
    if (!closed.IsDone())
      throw Error(ErrorCode::InvalidModel, "the riffled frame's line cannot be closed", {}, frame.xpath);
    line = closed.Wire();
  }
  gp_XYZ sum(0, 0, 0);
  for (const auto& position : frame.framePosition) sum += PositionRay::of(fuselage, position).origin.XYZ();
  const gp_Pnt middle(sum / static_cast<double>(frame.framePosition.size()));
  const gp_Pnt centre = fuselage.toGlobal(middle);
  const gp_Pln station(centre,
                       gp_Dir(gp_Vec(centre, fuselage.toGlobal(middle.Translated(gp_Vec(0, 1, 0))))
                                  .Crossed(gp_Vec(centre, fuselage.toGlobal(middle.Translated(gp_Vec(0, 0, 1)))))));
  return geometry::planeFaceWithin(station, line);
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
  return geometry::facesInside(compoundOf(stationSection(fuselage, frame)), side);
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
      faces = {planeWithinRiffledFrame(configuration, fuselage, frame)};
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
