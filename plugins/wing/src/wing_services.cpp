#include "wing_services.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <Eigen/Geometry>
#include <TopoDS_Compound.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/model/placement.h"
#include "airshape/wing/wing_list.h"
#include "component_segment.h"
#include "wing_geometry.h"
#include "wing_lookup.h"
#include "wing_profile.h"
#include "wing_shape.h"

namespace airshape::wing {

namespace {

/// An airfoil side (profile coordinates) placed by a segment end's transformation.
Handle(Geom_BSplineCurve) placedSide(const SegmentEnd& end, bool upper) {
  return geometry::transformed(upper ? end.profile->upperCurve() : end.profile->lowerCurve(), end.transform);
}

gp_Vec applyLinear(const model::Transform& transform, const gp_Vec& v) {
  const Eigen::Vector3d q = transform.linear() * Eigen::Vector3d(v.X(), v.Y(), v.Z());
  return {q.x(), q.y(), q.z()};
}

/// The wing airfoil (or rotor airfoil) definition of this uID; throws Error when none has it.
const schema::ProfileGeometryType& airfoilDefinition(const Configuration& configuration, const std::string& uid) {
  const schema::CpacsType& cpacs = configuration.cpacs();
  if (cpacs.vehicles && cpacs.vehicles->profiles) {
    const schema::ProfilesType& profiles = *cpacs.vehicles->profiles;
    if (profiles.wingAirfoils)
      for (const auto& airfoil : profiles.wingAirfoils->wingAirfoil)
        if (airfoil.uID == uid) return airfoil;
    if (profiles.rotorAirfoils)
      for (const auto& airfoil : profiles.rotorAirfoils->rotorAirfoil)
        if (airfoil.uID == uid) return airfoil;
  }
  throw Error(ErrorCode::InvalidModel, "airfoilUID '" + uid + "' names no wing airfoil");
}

class WingServicesOfThisPlugin final : public WingServices {
 public:
  const TopoDS_Shape& cleanSolid(const Configuration& configuration, const std::string& wingUid) const override {
    const graph::ComponentGraph& graph = configuration.components();
    const long index = graph.find(wingUid);
    const std::string type = index < 0 ? "" : graph.components()[static_cast<std::size_t>(index)].typeName;
    const bool isWing = type == "wing" || type == "rotor_blade";
    if (!isWing) throw Error(ErrorCode::InvalidArgument, "no wing with uID '" + wingUid + "'");
    return configuration.shapes().cleanNamedShapeOf(configuration, wingUid).shape;
  }

  gp_Pnt componentSegmentPoint(const Configuration& configuration, const std::string& componentSegmentUid, double eta,
                               double xsi, Surface surface) const override {
    const schema::WingType& wing = wingHolding(configuration, componentSegmentUid);
    const auto geometry = WingGeometry::of(configuration, wing);
    const ComponentSegment segment(*geometry, componentSegmentNamed(wing, componentSegmentUid));
    const ComponentSegment::SegmentPoint at = segment.toSegment(eta, xsi);
    switch (surface) {
      case Surface::Upper:
        return geometry->upperPoint(at.segment, at.eta, at.xsi);
      case Surface::Lower:
        return geometry->lowerPoint(at.segment, at.eta, at.xsi);
      default:
        return geometry->chordPoint(at.segment, at.eta, at.xsi);
    }
  }

  gp_Pnt pointRelativeTo(const Configuration& configuration, const std::string& componentSegmentUid,
                         const std::string& referenceUid, double eta, double xsi, Surface surface) const override {
    if (referenceUid.empty() || referenceUid == componentSegmentUid)
      return componentSegmentPoint(configuration, componentSegmentUid, eta, xsi, surface);
    const auto geometry = WingGeometry::of(configuration, wingHolding(configuration, componentSegmentUid));
    const std::vector<std::string>& uids = geometry->segmentUids();
    for (std::size_t k = 0; k < uids.size(); ++k) {
      if (uids[k] != referenceUid) continue;
      switch (surface) {
        case Surface::Upper:
          return geometry->upperPoint(k, eta, xsi);
        case Surface::Lower:
          return geometry->lowerPoint(k, eta, xsi);
        default:
          return geometry->chordPoint(k, eta, xsi);
      }
    }
    throw Error(ErrorCode::InvalidModel, "referenceUID '" + referenceUid + "' names neither component segment '" +
                                             componentSegmentUid + "' nor a segment of its wing");
  }

  std::vector<std::string> segmentUids(const Configuration& configuration, const std::string& wingUid) const override {
    return WingGeometry::of(configuration, wingNamed(configuration, wingUid))->segmentUids();
  }

  gp_Pnt segmentPoint(const Configuration& configuration, const std::string& wingUid, std::size_t segment, double eta,
                      double xsi, Surface surface) const override {
    const auto geometry = WingGeometry::of(configuration, wingNamed(configuration, wingUid));
    if (segment >= geometry->segments().size())
      throw Error(ErrorCode::InvalidArgument, "wing '" + wingUid + "' has no segment " + std::to_string(segment + 1));
    switch (surface) {
      case Surface::Upper:
        return geometry->upperPoint(segment, eta, xsi);
      case Surface::Lower:
        return geometry->lowerPoint(segment, eta, xsi);
      case Surface::Chord:
        break;
    }
    return geometry->chordPoint(segment, eta, xsi);
  }

  std::vector<std::string> componentSegmentSegmentUids(const Configuration& configuration,
                                                       const std::string& componentSegmentUid) const override {
    const schema::WingType& wing = wingHolding(configuration, componentSegmentUid);
    const auto geometry = WingGeometry::of(configuration, wing);
    const ComponentSegment segment(*geometry, componentSegmentNamed(wing, componentSegmentUid));
    std::vector<std::string> uids;
    for (std::size_t k : segment.segments()) uids.push_back(geometry->segmentUids()[k]);
    return uids;
  }

  AirfoilSides airfoilSides(const Configuration& configuration, const std::string& componentSegmentUid,
                            Surface surface) const override {
    const schema::WingType& wing = wingHolding(configuration, componentSegmentUid);
    const auto geometry = WingGeometry::of(configuration, wing);
    const bool upper = surface != Surface::Lower;
    AirfoilSides sides;
    sides.segmentUids = geometry->segmentUids();
    for (const WingSegment& segment : geometry->segments()) sides.sides.push_back(placedSide(segment.inner, upper));
    if (!geometry->segments().empty()) sides.sides.push_back(placedSide(geometry->segments().back().outer, upper));
    return sides;
  }

  const TopoDS_Shape& componentSegmentSolid(const Configuration& configuration,
                                            const std::string& componentSegmentUid) const override {
    const schema::WingType& wing = wingHolding(configuration, componentSegmentUid);
    const ComponentSegment segment(*WingGeometry::of(configuration, wing),
                                   componentSegmentNamed(wing, componentSegmentUid));
    const auto [first, last] = segment.segmentRange();
    return WingShape::of(configuration, wing)->closedSolidOf(first, last).shape;
  }

  TopoDS_Shape componentSegmentSkin(const Configuration& configuration, const std::string& componentSegmentUid,
                                    Surface surface) const override {
    const schema::WingType& wing = wingHolding(configuration, componentSegmentUid);
    const ComponentSegment segment(*WingGeometry::of(configuration, wing),
                                   componentSegmentNamed(wing, componentSegmentUid));
    const auto shape = WingShape::of(configuration, wing);
    BRep_Builder builder;
    TopoDS_Compound skin;
    builder.MakeCompound(skin);
    for (std::size_t k : segment.segments()) {
      const SegmentShape& faces = shape->segments()[k];
      const TopoDS_Face& face = surface == Surface::Lower && !faces.lower.IsNull() ? faces.lower : faces.upper;
      builder.Add(skin, face);
    }
    return skin;
  }

  double componentSegmentEta(const Configuration& configuration, const std::string& componentSegmentUid,
                             const std::string& referenceUid, double eta) const override {
    if (referenceUid.empty() || referenceUid == componentSegmentUid) return eta;
    const schema::WingType& wing = wingHolding(configuration, componentSegmentUid);
    const auto geometry = WingGeometry::of(configuration, wing);
    const ComponentSegment segment(*geometry, componentSegmentNamed(wing, componentSegmentUid));
    const std::vector<std::string>& uids = geometry->segmentUids();
    for (std::size_t k = 0; k < uids.size(); ++k)
      if (uids[k] == referenceUid) return segment.toComponentSegment(k, eta);
    throw Error(ErrorCode::InvalidModel, "referenceUID '" + referenceUid + "' names neither component segment '" +
                                             componentSegmentUid + "' nor one of its wing segments");
  }

  gp_Vec midplaneNormal(const Configuration& configuration, const std::string& componentSegmentUid,
                        double eta) const override {
    const schema::WingType& wing = wingHolding(configuration, componentSegmentUid);
    const auto geometry = WingGeometry::of(configuration, wing);
    const ComponentSegment segment(*geometry, componentSegmentNamed(wing, componentSegmentUid));
    const model::Transform toGlobal = model::componentTransform(configuration, wing.uID);
    const model::Transform toWing = toGlobal.inverse();
    const gp_Vec spanwise = leadingEdgeSeenFromFront(*geometry, segment, toWing, eta);
    const ComponentSegment::SegmentPoint front = segment.toSegment(eta, 0.0);
    const gp_Pnt leadingEdge = model::apply(toWing, geometry->chordPoint(front.segment, front.eta, 0.0));
    const gp_Pnt trailingEdge = model::apply(toWing, geometry->chordPoint(front.segment, front.eta, 1.0));
    const gp_Vec chord(leadingEdge, trailingEdge);
    if (chord.Magnitude() < 1e-15)
      throw Error(ErrorCode::InvalidModel,
                  "component segment '" + componentSegmentUid + "' has no chord at eta " + std::to_string(eta));
    return applyLinear(toGlobal, chord.Normalized().Crossed(spanwise));
  }

  TopoDS_Wire airfoilWire(const Configuration& configuration, const std::string& airfoilUid) const override {
    const WingProfile profile = WingProfile::fromDefinition(airfoilDefinition(configuration, airfoilUid));
    BRepBuilderAPI_MakeWire wire;
    // The lower side from the trailing edge to the leading edge, then the upper side: the
    // edges a wing-like loft skins one by one.
    Handle(Geom_BSplineCurve) lower = Handle(Geom_BSplineCurve)::DownCast(profile.lowerCurve()->Copy());
    lower->Reverse();
    const std::vector<Handle(Geom_BSplineCurve)> outline = {lower, profile.upperCurve()};
    for (const auto& curve : outline) wire.Add(BRepBuilderAPI_MakeEdge(curve).Edge());
    const gp_Pnt start = outline.front()->StartPoint(), end = outline.back()->EndPoint();
    if (start.Distance(end) > 1e-12) wire.Add(BRepBuilderAPI_MakeEdge(geometry::straightLine(end, start)).Edge());
    return wire.Wire();
  }

 private:
  /// The direction of the component segment's leading edge at eta, its points seen from the
  /// front (x dropped) in the wing's own frame, eta taken as a share of that line's length; at a
  /// kink of that line (within 1e-9 of its length) the bisector of the directions on either side
  /// (multiple_wings.xml's W11 cell, whose border lies on such a kink, has the reference's box and
  /// area so, and neither side's).
  static gp_Vec leadingEdgeSeenFromFront(const WingGeometry& geometry, const ComponentSegment& segment,
                                         const model::Transform& toWing, double eta) {
    std::vector<gp_Pnt> points;
    auto add = [&](const gp_Pnt& global) {
      const gp_Pnt local = model::apply(toWing, global);
      points.emplace_back(0.0, local.Y(), local.Z());
    };
    add(geometry.segments()[segment.segments().front()].inner.leadingEdge());
    for (std::size_t k : segment.segments()) add(geometry.segments()[k].outer.leadingEdge());
    double total = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) total += points[i - 1].Distance(points[i]);
    double travelled = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      const double piece = points[i - 1].Distance(points[i]);
      if (piece > 1e-15 && (travelled + piece >= eta * total || i + 1 == points.size())) {
        const gp_Vec here = gp_Vec(points[i - 1], points[i]).Normalized();
        if (std::abs(travelled + piece - eta * total) <= 1e-9 * total && i + 1 < points.size() &&
            points[i].Distance(points[i + 1]) > 1e-15)
          return (here + gp_Vec(points[i], points[i + 1]).Normalized()).Normalized();
        return here;
      }
      travelled += piece;
    }
    throw Error(ErrorCode::InvalidModel, "the leading edge of the component segment has no spanwise extent");
  }
};

}  // namespace

std::shared_ptr<const WingServices> makeWingServices() { return std::make_shared<WingServicesOfThisPlugin>(); }

}  // namespace airshape::wing
