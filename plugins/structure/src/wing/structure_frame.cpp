#include "structure_frame.h"

#include <algorithm>
#include <cmath>

#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <Eigen/Geometry>
#include <TopoDS_Compound.hxx>

#include "airshape/configuration.h"
#include "airshape/construction_guard.h"
#include "airshape/error.h"
#include "airshape/geometry/smallest_value.h"
#include "rib_cutter.h"
#include "rib_point.h"

namespace airshape::structure {

namespace {

using Surface = wing::WingServices::Surface;

gp_Vec linearly(const model::Transform& transform, const gp_Vec& v) {
  return gp_Vec(model::apply(transform, gp_Pnt(0, 0, 0)), model::apply(transform, gp_Pnt(v.XYZ())));
}

}  // namespace

StructureFrame::StructureFrame(const Configuration& configuration, const StructureServices& services,
                               std::string componentSegmentUid, std::string wingUid, std::string deviceUid)
    : configuration_(configuration),
      services_(services),
      componentSegmentUid_(std::move(componentSegmentUid)),
      deviceUid_(std::move(deviceUid)),
      toGlobal_(model::componentTransform(configuration, wingUid)),
      toWing_(toGlobal_.inverse()) {}

gp_Vec StructureFrame::toGlobal(const gp_Vec& v) const { return linearly(toGlobal_, v); }
gp_Vec StructureFrame::toWing(const gp_Vec& v) const { return linearly(toWing_, v); }

std::pair<double, double> StructureFrame::componentSegmentCoordinates(double eta, double xsi) const {
  if (!inDevice()) return {eta, xsi};
  const auto point = services_.devices.componentSegmentPoint(configuration_, deviceUid_, eta, xsi);
  return {point.eta, point.xsi};
}

gp_Pnt StructureFrame::chordPoint(const std::string& referenceUid, double eta, double xsi) const {
  if (inDevice()) return toWing(services_.devices.chordPoint(configuration_, deviceUid_, eta, xsi));
  return toWing(wing().pointRelativeTo(configuration_, componentSegmentUid_, referenceUid, eta, xsi, Surface::Chord));
}

double StructureFrame::frameEta(const std::string& referenceUid, double eta) const {
  if (inDevice()) return eta;
  return wing().componentSegmentEta(configuration_, componentSegmentUid_, referenceUid, eta);
}

double StructureFrame::etaOf(const gp_Pnt& point) const {
  // The distance to the chord line at eta is smallest at the point's eta. Its square is
  // smooth there, even for a point on the chord surface (where the distance has a corner), so
  // parabolas find it to rounding.
  auto squaredDistance = [&](double eta) {
    const gp_Pnt front = chordPoint("", eta, 0.0), back = chordPoint("", eta, 1.0);
    const gp_Vec chord(front, back);
    return gp_Vec(front, point).Crossed(chord).SquareMagnitude() / chord.SquareMagnitude();
  };
  return geometry::argumentOfMinimum(squaredDistance, 0.0, 1.0, 1e-12);
}

gp_Vec StructureFrame::midplaneNormal(double eta) const {
  const double csEta = componentSegmentCoordinates(std::clamp(eta, 0.0, 1.0), 0.5).first;
  return toWing(wing().midplaneNormal(configuration_, componentSegmentUid_, csEta)).Normalized();
}

gp_Vec StructureFrame::cellDirection() const {
  const gp_Pnt rootFront = chordPoint("", 0.0, 0.0), tipFront = chordPoint("", 1.0, 0.0);
  const gp_Vec seenFromFront(0.0, tipFront.Y() - rootFront.Y(), tipFront.Z() - rootFront.Z());
  const gp_Vec across = gp_Vec(rootFront, chordPoint("", 0.0, 1.0)).Crossed(seenFromFront);
  if (across.Magnitude() < 1e-12 * seenFromFront.Magnitude())
    throw Error(ErrorCode::InvalidModel, "the component segment's root chord runs along its leading edge");
  return across.Normalized();
}

std::vector<double> StructureFrame::sectionEtas() const {
  if (inDevice()) return {0.0, 1.0};  // the device's borders
  // Cached: every spar position asks whether it stands in a section.
  return *configuration_.cache().obtain<std::vector<double>>("section-etas:" + componentSegmentUid_, [&] {
    auto etas = std::make_shared<std::vector<double>>(1, 0.0);
    const std::vector<std::string> segments = wing().componentSegmentSegmentUids(configuration_, componentSegmentUid_);
    for (std::size_t k = 0; k + 1 < segments.size(); ++k)
      etas->push_back(wing().componentSegmentEta(configuration_, componentSegmentUid_, segments[k], 1.0));
    etas->push_back(1.0);
    return std::shared_ptr<const std::vector<double>>(etas);
  });
}

gp_Vec StructureFrame::thicknessDirection(double eta, double xsi) const {
  using Surface = wing::WingServices::Surface;
  const auto [csEta, csXsi] = componentSegmentCoordinates(eta, xsi);
  const gp_Pnt upper = wing().componentSegmentPoint(configuration_, componentSegmentUid_, csEta, csXsi, Surface::Upper);
  const gp_Pnt lower = wing().componentSegmentPoint(configuration_, componentSegmentUid_, csEta, csXsi, Surface::Lower);
  return toWing(gp_Vec(lower, upper));
}

gp_Vec StructureFrame::uprightAtSparPosition(double eta) const {
  if (inDevice()) return gp_Vec(0, 0, 1);  // a device's borders are no sections
  for (const double section : sectionEtas()) {
    if (std::abs(section - eta) > 1e-9) continue;
    const gp_Vec chord(chordPoint("", section, 0.0), chordPoint("", section, 1.0));
    const gp_Vec sectionNormal = chord.Crossed(thicknessDirection(section, 0.5));
    const gp_Vec upright = sectionNormal.Crossed(gp_Vec(1, 0, 0));
    if (upright.Magnitude() > 1e-12 * sectionNormal.Magnitude()) return upright.Normalized();
  }
  return gp_Vec(0, 0, 1);
}

gp_Vec StructureFrame::etaDirection(double eta) const {
  const geometry::Polyline edge = leadingEdge();
  std::vector<gp_Pnt> seenFromFront;
  for (const gp_Pnt& p : edge.points()) seenFromFront.emplace_back(0.0, p.Y(), p.Z());
  return geometry::Polyline(seenFromFront).directionAt(std::clamp(eta, 0.0, 1.0));
}

geometry::Polyline StructureFrame::edgeLine(bool trailing) const {
  auto edgePoint = [&](const std::string& segment, double eta) {
    return trailing ? sectionTrailingEdge(segment, eta) : chordPoint(segment, eta, 0.0);
  };
  // A device's edges within the wing are straight lines (the schema's controlSurface remarks).
  if (inDevice()) return geometry::Polyline({edgePoint("", 0.0), edgePoint("", 1.0)});
  const std::vector<std::string> segments = wing().componentSegmentSegmentUids(configuration_, componentSegmentUid_);
  std::vector<gp_Pnt> points = {edgePoint(segments.front(), 0.0)};
  for (const std::string& segment : segments) points.push_back(edgePoint(segment, 1.0));
  return geometry::Polyline(points);
}

gp_Pnt StructureFrame::sectionTrailingEdge(const std::string& segmentUid, double eta) const {
  if (inDevice()) return chordPoint(segmentUid, eta, 1.0);
  return toWing(wing().pointRelativeTo(configuration_, componentSegmentUid_, segmentUid, eta, 1.0, Surface::Upper));
}

geometry::Polyline StructureFrame::midplaneLine(const gp_Pnt& from, const gp_Pnt& to) const {
  const gp_Vec along(from, to);
  const gp_Vec normal = along.Crossed(gp_Vec(0, 0, 1));
  std::vector<std::pair<double, gp_Pnt>> crossings;
  const std::vector<std::string> segments = wing().componentSegmentSegmentUids(configuration_, componentSegmentUid_);
  for (std::size_t k = 0; k + 1 < segments.size(); ++k) {
    const gp_Pnt front = chordPoint(segments[k], 1.0, 0.0), back = sectionTrailingEdge(segments[k], 1.0);
    const double a = gp_Vec(from, front).Dot(normal), b = gp_Vec(from, back).Dot(normal);
    if (a == b) continue;
    const gp_Pnt crossing = front.Translated(a / (a - b) * gp_Vec(front, back));
    const double share = gp_Vec(from, crossing).Dot(along) / along.SquareMagnitude();
    if (share > 1e-9 && share < 1.0 - 1e-9) crossings.emplace_back(share, crossing);
  }
  std::sort(crossings.begin(), crossings.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  std::vector<gp_Pnt> points = {from};
  for (const auto& crossing : crossings) points.push_back(crossing.second);
  points.push_back(to);
  return geometry::Polyline(points);
}

gp_Pnt StructureFrame::positionPoint(const SparPosition& position) const {
  switch (position.kind) {
    case SparPosition::Kind::EtaXsi:
      return chordPoint(position.referenceUid, position.eta, position.xsi);
    case SparPosition::Kind::OnRib:
      return pointOnRib(configuration_, *this, position.ribsUid, position.ribNumber, position.xsi,
                        position.xpath + "/sparPositionRib");
    case SparPosition::Kind::OnCurve: {
      const std::string where = position.xpath + "/sparPositionCurve/referenceUID";
      // A spar positioned on a spar that is itself positioned on the first would be built for ever.
      const ConstructionGuard guard(
          "spar", position.referenceUid,
          "spar '" + position.referenceUid + "' is positioned on itself through spar positions on curves", where);
      return lineNamed(position.referenceUid, where).at(position.eta);
    }
  }
  throw Error(ErrorCode::InvalidModel, "unknown kind of spar position", {}, position.xpath);
}

geometry::Polyline StructureFrame::lineNamed(const std::string& name, const std::string& where) const {
  if (isWingEdge(name)) return isLeadingEdge(name) ? leadingEdge() : trailingEdge();
  try {
    return sparLine(sparSegmentNamed(configuration_, name));
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), error.message(), {}, where);
  }
}

geometry::Polyline StructureFrame::sparLine(const SparSegment& spar) const {
  std::vector<gp_Pnt> points;
  for (const SparPosition& position : spar.positions) {
    points.push_back(positionPoint(position));
  }
  if (points.size() < 2)
    throw Error(ErrorCode::InvalidModel, "a spar segment needs at least two spar positions", {},
                spar.xpath + "/sparPositionUIDs");
  geometry::Polyline line = midplaneLine(points[0], points[1]);
  for (std::size_t i = 2; i < points.size(); ++i) line = line.joined(midplaneLine(points[i - 1], points[i]));
  return line;
}

const TopoDS_Shape& StructureFrame::solid() const {
  if (inDevice()) return configuration_.shapes().shapeOf(configuration_, deviceUid_);
  return wing().componentSegmentSolid(configuration_, componentSegmentUid_);
}

TopoDS_Shape StructureFrame::componentSegmentSkin(bool upper) const {
  return wing().componentSegmentSkin(configuration_, componentSegmentUid_, upper ? Surface::Upper : Surface::Lower);
}

std::optional<TopoDS_Shape> StructureFrame::deviceCutter() const {
  if (!inDevice()) return std::nullopt;
  const controlsurfaces::DeviceServices::Cutter cutter = services_.devices.cutter(configuration_, deviceUid_);
  if (cutter.ownAirfoil) return std::nullopt;
  return cutter.solid;
}

TopoDS_Shape StructureFrame::skin(bool upper) const {
  if (!inDevice()) return componentSegmentSkin(upper);
  const NamedShape& device = configuration_.shapes().namedShapeOf(configuration_, deviceUid_);
  const std::string name = deviceUid_ + (upper ? "/upper" : "/lower");
  TopoDS_Compound faces;
  BRep_Builder builder;
  builder.MakeCompound(faces);
  for (const auto& [faceName, face] : device.faces)
    if (faceName == name) builder.Add(faces, face);
  return faces;
}

double StructureFrame::reach() const {
  // The box of the skins' poles holds the component segment (a B-spline lies in the hull of its
  // poles), without sewing the solid for it. Cached: each element of the structure asks.
  const std::string host = inDevice() ? deviceUid_ : componentSegmentUid_;
  return *configuration_.cache().obtain<double>("structure-reach:" + host, [&] {
    Bnd_Box box;
    for (const bool upper : {true, false}) BRepBndLib::Add(skin(upper), box, false);
    return std::make_shared<const double>(std::sqrt(box.SquareExtent()));
  });
}

}  // namespace airshape::structure
