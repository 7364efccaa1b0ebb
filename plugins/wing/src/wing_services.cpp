#include "wing_services.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "component_segment.h"
#include "wing_geometry.h"
#include "wing_lookup.h"

namespace airshape::wing {

namespace {

class WingServicesOfThisPlugin final : public WingServices {
 public:
  const TopoDS_Shape& cleanSolid(const Configuration& configuration, const std::string& wingUid) const override {
    const graph::ComponentGraph& graph = configuration.components();
    const long index = graph.find(wingUid);
    const std::string type = index < 0 ? "" : graph.components()[static_cast<std::size_t>(index)].typeName;
    const bool isWing = type == "wing" || type == "rotor_blade";
    if (!isWing) throw Error(ErrorCode::InvalidArgument, "no wing with uID '" + wingUid + "'");
    return configuration.shapes().shapeOf(configuration, wingUid);
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
};

}  // namespace

std::shared_ptr<const WingServices> makeWingServices() { return std::make_shared<WingServicesOfThisPlugin>(); }

}  // namespace airshape::wing
