// A third-party plugin with component kinds of its own, built against an installed Airshape
// (find_package(airshape)): sensor arrays (groups of their members), their sensor boxes
// (solids), their cables (lines), and sensors that sit inside a wing, placed on its component
// segment through the wing plugin's public interface. None of these elements is CPACS: the
// plugin reads them from the document itself.
//
//   <sensorArrays><sensorArray uID="A">
//     <boxes><box uID="B"><x>..</x><y>..</y><z>..</z><dx>..</dx><dy>..</dy><dz>..</dz></box></boxes>
//     <cables><cable uID="C"><points>x;y;z;x;y;z;...</points></cable></cables>
//   </sensorArray></sensorArrays>
//   <wing ...><sensors><sensor uID="S"><componentSegmentUID>..</componentSegmentUID>
//     <eta>..</eta><xsi>..</xsi><radius>..</radius></sensor></sensors></wing>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <airshape/configuration.h>
#include <airshape/error.h>
#include <airshape/model/placement.h>
#include <airshape/plugin/basic_plugin.h>
#include <airshape/wing/wing_services.h>
#include <airshape/xml/text.h>

namespace {

using airshape::Configuration;
using airshape::NamedShape;
using airshape::plugin::NodeType;

const xercesc::DOMElement& elementOf(const Configuration& configuration, const std::string& uid) {
  return *configuration.components().named(uid).element;
}

/// The number in a child element, naming the element's path when it is missing or no number.
double number(const Configuration& configuration, const std::string& uid, const char* child) {
  const xercesc::DOMElement* element = airshape::xml::firstChild(elementOf(configuration, uid), child);
  const std::string path = configuration.components().named(uid).xpath + "/" + child;
  if (element == nullptr) throw airshape::Error(airshape::ErrorCode::InvalidModel, "missing", {}, path);
  return airshape::model::finite(std::stod(airshape::xml::text(*element)), path);
}

/// Its faces named "<uID>/side<i>", as the built-in kinds name theirs.
NamedShape named(const TopoDS_Shape& shape, const std::string& uid) {
  NamedShape result{shape, {}};
  int index = 0;
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next())
    result.faces.emplace_back(uid + "/side" + std::to_string(++index), TopoDS::Face(face.Current()));
  return result;
}

NamedShape sensorBox(const Configuration& c, const std::string& uid) {
  const gp_Pnt corner(number(c, uid, "x"), number(c, uid, "y"), number(c, uid, "z"));
  return named(BRepPrimAPI_MakeBox(corner, number(c, uid, "dx"), number(c, uid, "dy"), number(c, uid, "dz")).Shape(),
               uid);
}

/// A cable is a line: a polyline through its points, no faces.
NamedShape sensorCable(const Configuration& c, const std::string& uid) {
  const xercesc::DOMElement* points = airshape::xml::firstChild(elementOf(c, uid), "points");
  const std::string path = c.components().named(uid).xpath + "/points";
  if (points == nullptr) throw airshape::Error(airshape::ErrorCode::InvalidModel, "missing", {}, path);
  const std::vector<double> xyz = airshape::model::parseVector(airshape::xml::text(*points), path);
  BRepBuilderAPI_MakePolygon polyline;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) polyline.Add(gp_Pnt(xyz[i], xyz[i + 1], xyz[i + 2]));
  return {polyline.Wire(), {}};
}

/// The array: its boxes and cables side by side.
NamedShape sensorArray(const Configuration& c, const std::string& uid) {
  std::vector<const NamedShape*> members;
  for (const airshape::graph::Component& component : c.components().components())
    if (component.parentUid == uid) members.push_back(&c.shapes().namedShapeOf(c, component.uid));
  if (members.empty()) throw airshape::NoShape("the array has no members: no shape", c.components().named(uid).xpath);
  return airshape::compoundOfNamedShapes(members);
}

std::vector<NodeType> declaredNodeTypes() {
  return {NodeType{"sensorArray", "sensorArrays/sensorArray"}.typed("sensor_array").asGroup(),
          NodeType{"sensorBox", "boxes/box"}.inside("sensorArray").typed("sensor_box").inBox(),
          NodeType{"sensorCable", "cables/cable"}.inside("sensorArray").typed("sensor_cable"),
          NodeType{"wingSensor", "sensors/sensor"}.inside("wing").typed("wing_sensor").asInsideParent()};
}

class SensorArrayPlugin final : public airshape::plugin::BasicPlugin {
 public:
  SensorArrayPlugin()
      : BasicPlugin("sensorarrays", "0.1.0", "sensor arrays, boxes, cables and wing sensors (a third-party example)",
                    declaredNodeTypes(), {{"wing", "0.1.0", "1.0.0"}}) {}

  void useServices(const airshape::plugin::ServiceRegistry& services) override {
    wing_ = services.find<airshape::wing::WingServices>(airshape::wing::kWingServices);
  }

  void registerShapeBuilders(airshape::ComponentShapes& shapes) const override {
    shapes.add("sensorBox", sensorBox);
    shapes.add("sensorCable", sensorCable);
    shapes.add("sensorArray", sensorArray);
    const auto wing = wing_;
    shapes.add("wingSensor", [wing](const Configuration& c, const std::string& uid) {
      const xercesc::DOMElement* segment = airshape::xml::firstChild(elementOf(c, uid), "componentSegmentUID");
      if (segment == nullptr)
        throw airshape::Error(airshape::ErrorCode::InvalidModel, "missing", {},
                              c.components().named(uid).xpath + "/componentSegmentUID");
      const gp_Pnt centre =
          wing->componentSegmentPoint(c, airshape::xml::text(*segment), number(c, uid, "eta"), number(c, uid, "xsi"),
                                      airshape::wing::WingServices::Surface::Chord);
      return named(BRepPrimAPI_MakeSphere(centre, number(c, uid, "radius")).Shape(), uid);
    });
  }

 private:
  std::shared_ptr<const airshape::wing::WingServices> wing_;
};

}  // namespace

AIRSHAPE_PLUGIN(SensorArrayPlugin)
