// The wing plugin: CPACS wings. It answers the wing ops that need no geometry; the
// geometry ops are registered as pending until the wing builder exists.
#include <algorithm>

#include <BRepAlgoAPI_Cut.hxx>
#include <Eigen/Geometry>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/model/segment_chain.h"
#include "airshape/model/symmetry.h"
#include "airshape/plugin/basic_plugin.h"
#include "airshape/query/arguments.h"
#include "airshape/query/model_selection.h"
#include "airshape/wing/wing_list.h"
#include "component_segment.h"
#include "segment_locator.h"
#include "wing_geometry.h"
#include "wing_lookup.h"
#include "wing_measures.h"
#include "wing_services.h"
#include "wing_shape.h"

namespace airshape::wing {

using query::Json;

namespace {

/// The wing a query names by index or uID, in the model queries address (the first one).
schema::WingType& selectWing(const Configuration& configuration, const Json& query) {
  return query::selectInFirstModel(configuration, wingsOf(configuration), wingNodeTypes(), query, "wing", "wing");
}

std::size_t segmentCount(const schema::WingType& wing) { return wing.segments ? wing.segments->segment.size() : 0; }
std::size_t sectionCount(const schema::WingType& wing) { return wing.sections ? wing.sections->section.size() : 0; }
std::size_t componentSegmentCount(const schema::WingType& wing) {
  return wing.componentSegments ? wing.componentSegments->componentSegment.size() : 0;
}

Json asJson(const gp_Pnt& p) { return Json::array({p.X(), p.Y(), p.Z()}); }

const schema::ComponentSegmentType& selectComponentSegment(const schema::WingType& wing, const Json& q) {
  std::vector<std::string> uids;
  if (wing.componentSegments)
    for (const auto& cs : wing.componentSegments->componentSegment) uids.push_back(cs.uID);
  // Selecting first: it refuses any index or uID of a wing without component segments.
  const std::size_t index = query::selectByIndexOrUid(q, "component_segment", uids, "component segment");
  return wing.componentSegments->componentSegment[index];
}

/// A point query: wing, segment (index or uID, in chain order), eta and xsi in [0, 1].
template <class Point>
query::Handler pointQuery(Point point) {
  return [point](Configuration& c, const Json& q) -> Json {
    const auto geometry = WingGeometry::of(c, selectWing(c, q));
    const std::size_t segment = query::selectByIndexOrUid(q, "segment", geometry->segmentUids(), "segment");
    return asJson(point(*geometry, segment, query::fractionArgument(q, "eta"), query::fractionArgument(q, "xsi")));
  };
}

/// A per-segment measure query: wing, segment (index or uID, in chain order).
query::Handler segmentMeasure(double (WingShape::*measure)(std::size_t) const) {
  return [measure](Configuration& c, const Json& q) -> Json {
    const schema::WingType& wing = selectWing(c, q);
    const std::size_t segment =
        query::selectByIndexOrUid(q, "segment", WingGeometry::of(c, wing)->segmentUids(), "segment");
    return (*WingShape::of(c, wing).*measure)(segment);
  };
}

/// Wings and rotor blades, and inside each its segments and component segments (parts of its
/// solid that queries measure).
std::vector<plugin::NodeType> declaredNodeTypes() {
  using plugin::NodeType;
  std::vector<NodeType> types = {NodeType{"wing", "wings/wing"}.inBox().placedByItsTransformation().leftOutWhen(
                                     model::segmentsFormNoChain<schema::WingType>),
                                 NodeType{"rotorBlade", "rotorBlades/rotorBlade"}
                                     .typed("rotor_blade")
                                     .placedByItsTransformation()
                                     .leftOutWhen(model::segmentsFormNoChain<schema::WingType>)};
  for (const char* body : {"wing", "rotorBlade"}) {
    types.push_back(NodeType{"wingSegment", "segments/segment"}.inside(body).typed("wing_segment").asPart());
    types.push_back(NodeType{"wingComponentSegment", "componentSegments/componentSegment"}
                        .inside(body)
                        .typed("wing_component_segment")
                        .asPart());
  }
  return types;
}

class WingPlugin final : public plugin::BasicPlugin {
 public:
  void registerShapeBuilders(ComponentShapes& shapes) const override {
    const ShapeBuilder wingSolid = [](const Configuration& c, const std::string& uid) {
      const schema::WingType& wing = wingNamed(c, uid);
      return WingShape::of(c, wing)->solid();
    };
    shapes.add("wing", wingSolid);
    shapes.add("rotorBlade", wingSolid);  // a rotor blade is a wing in its own frame
    shapes.add("wingSegment", [](const Configuration& c, const std::string& uid) {
      const schema::WingType& wing = wingHolding(c, uid);
      const auto& uids = WingGeometry::of(c, wing)->segmentUids();
      const auto segment = static_cast<std::size_t>(std::find(uids.begin(), uids.end(), uid) - uids.begin());
      return WingShape::of(c, wing)->solidOf(segment, segment);
    });
    shapes.add("wingComponentSegment", [](const Configuration& c, const std::string& uid) {
      const schema::WingType& wing = wingHolding(c, uid);
      const ComponentSegment segment(*WingGeometry::of(c, wing), componentSegmentNamed(wing, uid));
      const auto [first, last] = segment.segmentRange();
      return WingShape::of(c, wing)->componentSegmentShape(first, last);
    });
  }

  void offerServices(plugin::ServiceRegistry& services) const override {
    services.offer<WingServices>(kWingServices, makeWingServices());
  }

  WingPlugin()
      : BasicPlugin("wing", "0.1.0", "CPACS wings: profiles, sections, segments, component segments",
                    declaredNodeTypes()) {}

  void registerQueries(query::QueryRegistry& registry) const override {
    registry.add({"wing_count", "", "-> number of wings of the model",
                  [](Configuration& c, const Json&) -> Json { return wingsOf(c).size(); }});
    registry.add(
        {"wing_uid", "", "wing -> uID", [](Configuration& c, const Json& q) -> Json { return selectWing(c, q).uID; }});
    registry.add({"wing_segment_count", "", "wing -> number of segments",
                  [](Configuration& c, const Json& q) -> Json { return segmentCount(selectWing(c, q)); }});
    registry.add({"wing_section_count", "", "wing -> number of sections",
                  [](Configuration& c, const Json& q) -> Json { return sectionCount(selectWing(c, q)); }});
    registry.add({"wing_component_segment_count", "", "wing -> number of component segments",
                  [](Configuration& c, const Json& q) -> Json { return componentSegmentCount(selectWing(c, q)); }});
    registry.add(
        {"wing_symmetry", "", "wing -> \"none\", \"x-y\", \"x-z\" or \"y-z\" (inherited through parentUID)",
         [](Configuration& c, const Json& q) -> Json { return model::resolvedSymmetry(c, selectWing(c, q).uID); }});
    registry.add(
        {"wing_upper_point", "", "wing, segment, eta, xsi -> point on the upper skin",
         pointQuery([](const WingGeometry& g, std::size_t s, double e, double x) { return g.upperPoint(s, e, x); })});
    registry.add(
        {"wing_lower_point", "", "wing, segment, eta, xsi -> point on the lower skin",
         pointQuery([](const WingGeometry& g, std::size_t s, double e, double x) { return g.lowerPoint(s, e, x); })});
    registry.add(
        {"wing_chord_point", "", "wing, segment, eta, xsi -> point on the chord surface",
         pointQuery([](const WingGeometry& g, std::size_t s, double e, double x) { return g.chordPoint(s, e, x); })});
    registry.add({"wing_reference_area", "", "wing, plane -> projected area of the chord surfaces",
                  [](Configuration& c, const Json& q) -> Json {
                    return referenceArea(*WingGeometry::of(c, selectWing(c, q)), query::stringArgument(q, "plane"));
                  }});
    registry.add({"wing_mac", "", "wing -> {mac, point}: mean aerodynamic chord and its leading edge",
                  [](Configuration& c, const Json& q) -> Json {
                    const MeanAerodynamicChord mac = meanAerodynamicChord(*WingGeometry::of(c, selectWing(c, q)));
                    return {{"mac", mac.length}, {"point", asJson(mac.leadingEdge)}};
                  }});
    registry.add(
        {"wing_span", "", "wing -> span (tip to tip where mirrored)", [](Configuration& c, const Json& q) -> Json {
           const schema::WingType& wing = selectWing(c, q);
           const model::Transform unparented = model::transformationMatrix(wing.transformation.get()) *
                                               model::componentTransform(c, wing.uID).inverse();
           return span(*WingGeometry::of(c, wing), model::resolvedSymmetry(c, wing.uID), unparented);
         }});
    registry.add({"component_segment_to_segment", "", "wing, component_segment, eta, xsi -> {segment, eta, xsi}",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::WingType& wing = selectWing(c, q);
                    const auto geometry = WingGeometry::of(c, wing);
                    const ComponentSegment cs(*geometry, selectComponentSegment(wing, q));
                    const auto p = cs.toSegment(query::fractionArgument(q, "eta"), query::fractionArgument(q, "xsi"));
                    return {{"segment", geometry->segments()[p.segment].uid}, {"eta", p.eta}, {"xsi", p.xsi}};
                  }});
    registry.add({"segment_to_component_segment", "", "wing, segment, component_segment, eta, xsi -> {eta, xsi}",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::WingType& wing = selectWing(c, q);
                    const auto geometry = WingGeometry::of(c, wing);
                    const std::size_t segment =
                        query::selectByIndexOrUid(q, "segment", geometry->segmentUids(), "segment");
                    const ComponentSegment cs(*geometry, selectComponentSegment(wing, q));
                    const double eta = query::fractionArgument(q, "eta"), xsi = query::fractionArgument(q, "xsi");
                    return {{"eta", cs.toComponentSegment(segment, eta)}, {"xsi", xsi}};
                  }});
    registry.add({"wing_volume", "", "wing -> volume (with what others cut out of it, such as ducts, when that is on)",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::WingType& wing = selectWing(c, q);
                    if (c.shapes().isCutByOthers(c, wing.uID))
                      return geometry::enclosedVolume(c.shapes().shapeOf(c, wing.uID));
                    return WingShape::of(c, wing)->volume();
                  }});
    registry.add({"wing_surface_area", "",
                  "wing -> area of the whole loft (skins, caps, trailing-edge strips; the walls of cut-outs)",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::WingType& wing = selectWing(c, q);
                    if (c.shapes().isCutByOthers(c, wing.uID)) return geometry::areaOf(c.shapes().shapeOf(c, wing.uID));
                    return WingShape::of(c, wing)->surfaceArea();
                  }});
    registry.add({"wing_segment_volume", "", "wing, segment -> volume", segmentMeasure(&WingShape::segmentVolume)});
    registry.add({"wing_segment_surface_area", "", "wing, segment -> area of the upper and lower skin",
                  segmentMeasure(&WingShape::segmentSurfaceArea)});
    registry.add({"wing_segment_eta_xsi", "", "wing, x, y, z -> {segment, eta, xsi, on_top} of the nearest skin point",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::WingType& wing = selectWing(c, q);
                    const auto geometry = WingGeometry::of(c, wing);
                    const gp_Pnt point(query::numberArgument(q, "x"), query::numberArgument(q, "y"),
                                       query::numberArgument(q, "z"));
                    const auto location = locateOnWing(*geometry, *WingShape::of(c, wing), point);
                    if (!location)
                      throw Error(ErrorCode::InvalidArgument,
                                  "the point lies on no segment of wing '" + wing.uID + "'");
                    return {{"segment", geometry->segmentUids()[location->segment]},
                            {"eta", location->eta},
                            {"xsi", location->xsi},
                            {"on_top", location->onTop}};
                  }});
    registry.add({"wing_wetted_area", "", "wing -> area of the wing solid outside its parent component",
                  [](Configuration& c, const Json& q) -> Json {
                    const schema::WingType& wing = selectWing(c, q);
                    const auto shape = WingShape::of(c, wing);
                    const std::string parent = wing.parentUID.value_or("");
                    if (parent.empty() || c.components().find(parent) < 0) return shape->surfaceArea();
                    const TopoDS_Shape cut =
                        BRepAlgoAPI_Cut(c.shapes().shapeOf(c, wing.uID), c.shapes().shapeOf(c, parent)).Shape();
                    return geometry::areaOf(cut);
                  }});
  }
};

}  // namespace
}  // namespace airshape::wing

AIRSHAPE_PLUGIN(airshape::wing::WingPlugin)
