#include "position_rays.h"

#include <algorithm>
#include <cmath>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "fuselage_frame.h"

namespace airshape::structure {

namespace {

constexpr double kDegrees = M_PI / 180.0;

Handle(Geom_BSplineCurve) rayLine(const FuselageFrame& fuselage, const PositionRay& ray, double length) {
  // Both ends carried to the global frame, so that the ruled surfaces between the rays are the
  // same whatever the fuselage's transformation.
  return geometry::straightLine(fuselage.toGlobal(ray.origin),
                                fuselage.toGlobal(ray.origin.Translated(ray.direction * length)));
}

/// Whether four points lie in one plane to `tolerance`.
bool planar(const std::vector<gp_Pnt>& corners, double tolerance) {
  const gp_Vec normal = gp_Vec(corners[0], corners[1]).Crossed(gp_Vec(corners[0], corners[2]));
  if (normal.Magnitude() <= tolerance * tolerance) return false;
  return std::abs(gp_Vec(corners[0], corners[3]).Dot(normal.Normalized())) <= tolerance;
}

}  // namespace

PositionRay PositionRay::of(const FuselageFrame& fuselage, const schema::StringerFramePositionType& position) {
  const double angle = position.referenceAngle * kDegrees;
  return {gp_Pnt(fuselage.positionX(position), position.referenceY, position.referenceZ),
          gp_Vec(0.0, -std::sin(angle), std::cos(angle))};
}

PositionRay PositionRay::between(const PositionRay& a, const PositionRay& b, double share) {
  return {gp_Pnt(a.origin.XYZ() * (1.0 - share) + b.origin.XYZ() * share),
          a.direction * (1.0 - share) + b.direction * share};
}

TopoDS_Face ruledBetween(const FuselageFrame& fuselage, const PositionRay& a, const PositionRay& b, double length) {
  // Rays in one plane (equal angles, or one station) bound a plane face: the skin's section by a
  // plane is found much faster than by a general ruled surface.
  std::vector<gp_Pnt> corners;
  for (const gp_Pnt& corner :
       {a.origin, a.origin.Translated(a.direction * length), b.origin.Translated(b.direction * length), b.origin})
    if (corners.empty() || !corner.IsEqual(corners.back(), 1e-9 * length)) corners.push_back(corner);
  if (corners.size() == 3 || planar(corners, 1e-9 * length)) {
    BRepBuilderAPI_MakePolygon outline;
    for (const gp_Pnt& corner : corners) outline.Add(fuselage.toGlobal(corner));
    outline.Close();
    BRepBuilderAPI_MakeFace face(outline.Wire(), true);
    if (face.IsDone()) return face.Face();
  }
  return geometry::ruledFace(rayLine(fuselage, a, length), rayLine(fuselage, b, length));
}

StringerPath::StringerPath(const FuselageFrame& fuselage, const schema::StringerType& stringer) {
  for (const schema::StringerFramePositionType& position : stringer.stringerPosition)
    positions_.push_back(PositionRay::of(fuselage, position));
  if (positions_.empty()) throw Error(ErrorCode::InvalidModel, "the stringer has no position", {}, stringer.xpath);
  std::stable_sort(positions_.begin(), positions_.end(),
                   [](const PositionRay& a, const PositionRay& b) { return a.origin.X() < b.origin.X(); });
}

PositionRay StringerPath::rayAt(double x) const {
  for (std::size_t k = 1; k < positions_.size(); ++k) {
    const PositionRay& before = positions_[k - 1];
    const PositionRay& after = positions_[k];
    if (x < before.origin.X() || x > after.origin.X()) continue;
    const double run = after.origin.X() - before.origin.X();
    return run > 0.0 ? PositionRay::between(before, after, (x - before.origin.X()) / run) : after;
  }
  PositionRay ray = x <= firstX() ? positions_.front() : positions_.back();
  ray.origin.SetX(x);
  return ray;
}

std::vector<RaySpan> StringerPath::spans(double fromX, double toX) const {
  // The stations where the surface bends: the ends and the positions between them.
  std::vector<double> stations{fromX};
  for (const PositionRay& position : positions_)
    if (position.origin.X() > fromX && position.origin.X() < toX) stations.push_back(position.origin.X());
  stations.push_back(toX);
  std::vector<RaySpan> spans;
  for (std::size_t k = 1; k < stations.size(); ++k)
    if (stations[k] > stations[k - 1]) spans.emplace_back(rayAt(stations[k - 1]), rayAt(stations[k]));
  return spans;
}

std::vector<TopoDS_Face> StringerPath::surface(const FuselageFrame& fuselage, double fromX, double toX,
                                               double length) const {
  std::vector<TopoDS_Face> faces;
  for (const auto& [from, to] : spans(fromX, toX)) faces.push_back(ruledBetween(fuselage, from, to, length));
  return faces;
}

std::vector<RaySpan> frameSpans(const FuselageFrame& fuselage, const schema::FrameType& frame) {
  if (fuselage.offFirstStation(frame) != nullptr) return riffledFrameSpans(fuselage, frame);
  std::vector<RaySpan> spans;
  for (std::size_t k = 1; k < frame.framePosition.size(); ++k)
    spans.emplace_back(PositionRay::of(fuselage, frame.framePosition[k - 1]),
                       PositionRay::of(fuselage, frame.framePosition[k]));
  return spans;
}

std::vector<RaySpan> riffledFrameSpans(const FuselageFrame& fuselage, const schema::FrameType& frame) {
  // Where a ray meets the skin, in fuselage coordinates.
  const auto onSkin = [&](const PositionRay& ray, const std::string& where) {
    return fuselage.toLocal(
        fuselage.skinAhead(fuselage.toGlobal(ray.origin), fuselage.toGlobal(gp_Dir(ray.direction)), where));
  };
  // The rays from `centre` through the points of the chord from `from` to `to`: linearly blended,
  // they sweep the plane through the three points, and meet the skin along its section there.
  const auto fan = [](const gp_Pnt& centre, const gp_Pnt& from, const gp_Pnt& to) {
    return RaySpan{{centre, gp_Vec(centre, from)}, {centre, gp_Vec(centre, to)}};
  };
  std::vector<RaySpan> spans;
  for (std::size_t k = 1; k < frame.framePosition.size(); ++k) {
    const schema::StringerFramePositionType &first = frame.framePosition[k - 1], &second = frame.framePosition[k];
    const PositionRay a = PositionRay::of(fuselage, first), b = PositionRay::of(fuselage, second);
    const double middleAngle = 0.5 * (first.referenceAngle + second.referenceAngle) * kDegrees;
    const PositionRay middle{gp_Pnt(0.5 * (a.origin.XYZ() + b.origin.XYZ())),
                             gp_Vec(0.0, -std::sin(middleAngle), std::cos(middleAngle))};
    const gp_Pnt from = onSkin(a, first.xpath), halfway = onSkin(middle, frame.xpath), to = onSkin(b, second.xpath);
    // The first half is seen from three quarters of the way to the second reference point, the
    // second half from a quarter of the way (as the reference library draws them).
    const gp_Pnt seesFirstHalf(0.25 * a.origin.XYZ() + 0.75 * b.origin.XYZ());
    const gp_Pnt seesSecondHalf(0.75 * a.origin.XYZ() + 0.25 * b.origin.XYZ());
    spans.push_back(fan(seesFirstHalf, from, halfway));
    spans.push_back(fan(seesSecondHalf, halfway, to));
  }
  return spans;
}

std::vector<RaySpan> ringSpans(const FuselageFrame& fuselage, const schema::FrameType& frame) {
  const schema::StringerFramePositionType& position = frame.framePosition[0];
  const gp_Pnt origin(fuselage.stationX(frame), position.referenceY, position.referenceZ);
  auto rayAt = [&](int quarter) {
    const double angle = quarter * M_PI / 2.0;
    return PositionRay{origin, gp_Vec(0.0, -std::sin(angle), std::cos(angle))};
  };
  std::vector<RaySpan> spans;
  for (int quarter = 0; quarter < 4; ++quarter) spans.emplace_back(rayAt(quarter), rayAt(quarter + 1));
  return spans;
}

std::vector<TopoDS_Face> frameSweep(const FuselageFrame& fuselage, const schema::FrameType& frame, double length) {
  std::vector<TopoDS_Face> faces;
  for (const auto& [from, to] : frameSpans(fuselage, frame)) faces.push_back(ruledBetween(fuselage, from, to, length));
  return faces;
}

}  // namespace airshape::structure
