#include "element_geometry.h"

#include <cmath>
#include <functional>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepPrimAPI_MakeWedge.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/schema/element_reading.h"
#include "airshape/xml/path.h"
#include "external_file.h"

namespace airshape::generic {

namespace {

using xercesc::DOMElement;

/// The elements of a list child: <cuboids><cuboid/>...</cuboids>.
std::vector<const DOMElement*> listed(const DOMElement& geometry, const std::string& list, const std::string& item) {
  std::vector<const DOMElement*> items;
  if (const DOMElement* parent = xml::firstChild(geometry, list))
    for (const DOMElement* child = xml::firstElement(*parent); child != nullptr; child = xml::nextElement(*child))
      if (xml::name(*child) == item) items.push_back(child);
  return items;
}

double required(const DOMElement& part, const std::string& name, const std::string& xpath) {
  const std::optional<double> value = schema::numberIn(part, name, xpath);
  if (!value) throw Error(ErrorCode::InvalidModel, "no " + name + " given", {}, xpath);
  return *value;
}

void requirePositive(double value, const std::string& what, const std::string& xpath) {
  if (value <= 0.0) throw Error(ErrorCode::InvalidModel, what + " must be positive", {}, xpath);
}

model::Transform transformationOf(const DOMElement& element, const std::string& xpath) {
  return model::transformationMatrix(
      schema::readChild<schema::TransformationType>(element, "transformation", xpath).get());
}

/// A cuboid from the origin along x, y and z, its upper face (z = heightZ) narrowed to
/// [upperFaceXmin, upperFaceXmax] x [upperFaceYmin, upperFaceYmax] where given.
TopoDS_Shape cuboid(const DOMElement& part, const std::string& xpath) {
  const double lengthX = required(part, "lengthX", xpath), depthY = required(part, "depthY", xpath),
               heightZ = required(part, "heightZ", xpath);
  if (lengthX <= 0.0 || depthY <= 0.0 || heightZ <= 0.0)
    throw Error(ErrorCode::InvalidModel, "lengthX, depthY and heightZ must be positive", {}, xpath);
  const double xMin = schema::numberIn(part, "upperFaceXmin", xpath).value_or(0.0);
  const double xMax = schema::numberIn(part, "upperFaceXmax", xpath).value_or(lengthX);
  const double yMin = schema::numberIn(part, "upperFaceYmin", xpath).value_or(0.0);
  const double yMax = schema::numberIn(part, "upperFaceYmax", xpath).value_or(depthY);
  // OCCT's wedge rises along its y axis, its top face spanning [xmin, xmax] x [zmin, zmax]:
  // turned about x by 90° (y up to z, z to -y) and moved by depthY along y it is the cuboid.
  const TopoDS_Shape wedge =
      BRepPrimAPI_MakeWedge(lengthX, heightZ, depthY, xMin, depthY - yMax, xMax, depthY - yMin).Shape();
  gp_Trsf turn, shift;
  turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), M_PI / 2);
  shift.SetTranslation(gp_Vec(0, depthY, 0));
  return wedge.Moved(TopLoc_Location(shift * turn));
}

/// A cylinder or cone on the xy plane about the z axis, `height` high.
TopoDS_Shape cone(double lowerRadius, double upperRadius, double height) {
  if (std::abs(lowerRadius - upperRadius) < 1e-8) return BRepPrimAPI_MakeCylinder(lowerRadius, height).Shape();
  return BRepPrimAPI_MakeCone(lowerRadius, upperRadius, height).Shape();
}

/// Revolution angles (ellipsoids, tori) are in radians in the CPACS versions that have them.
double revolutionAngle(const DOMElement& part, const std::string& xpath) {
  const double angle = schema::numberIn(part, "revolutionAngle", xpath).value_or(2 * M_PI);
  if (angle <= 0.0 || angle > 2 * M_PI)
    throw Error(ErrorCode::InvalidModel, "the revolution angle must lie in (0, 2 pi]", {}, xpath + "/revolutionAngle");
  return angle;
}

/// One part: its shape in its own frame and the map that places it within the element.
struct Part {
  std::string kind;
  TopoDS_Shape shape;
  model::Transform transform;
};

/// A parallelepiped (CPACS 3.5) from the origin: edges a along x, b in the xy plane at
/// gamma from a, c at alpha from b and beta from a (angles in degrees, 90 where left out).
Part parallelepiped(const DOMElement& part, const std::string& xpath) {
  const double a = required(part, "a", xpath), b = required(part, "b", xpath), c = required(part, "c", xpath);
  if (a <= 0.0 || b <= 0.0 || c <= 0.0) throw Error(ErrorCode::InvalidModel, "a, b and c must be positive", {}, xpath);
  const auto angle = [&](const char* name) { return schema::numberIn(part, name, xpath).value_or(90.0) * M_PI / 180; };
  const double alpha = angle("alpha"), beta = angle("beta"), gamma = angle("gamma");
  const double cx = std::cos(beta), cy = (std::cos(alpha) - std::cos(beta) * std::cos(gamma)) / std::sin(gamma);
  const double cz2 = 1.0 - cx * cx - cy * cy;
  if (cz2 <= 0.0) throw Error(ErrorCode::InvalidModel, "the angles span no volume", {}, xpath);
  model::Transform edges = model::Transform::Identity();
  edges.linear() << 1.0, std::cos(gamma), cx, 0.0, std::sin(gamma), cy, 0.0, 0.0, std::sqrt(cz2);
  return {"parallelepiped", BRepPrimAPI_MakeBox(a, b, c).Shape(), edges};
}

Part primitive(const std::string& kind, const DOMElement& part, const std::string& xpath) {
  const model::Transform own = transformationOf(part, xpath);
  if (kind == "cuboid") return {kind, cuboid(part, xpath), own};
  if (kind == "parallelepiped") return parallelepiped(part, xpath);
  if (kind == "sphere") {
    const double radius = required(part, "radius", xpath);
    requirePositive(radius, "the radius", xpath);
    return {kind, BRepPrimAPI_MakeSphere(radius).Shape(), own};
  }
  if (kind == "boundingBox") {
    const double x = required(part, "deltaX", xpath), y = required(part, "deltaY", xpath),
                 z = required(part, "deltaZ", xpath);
    if (x <= 0.0 || y <= 0.0 || z <= 0.0)
      throw Error(ErrorCode::InvalidModel, "deltaX, deltaY and deltaZ must be positive", {}, xpath);
    const auto origin = schema::readChild<schema::PointType>(part, "origin", xpath);
    const gp_Pnt corner(origin && origin->x ? *origin->x : 0.0, origin && origin->y ? *origin->y : 0.0,
                        origin && origin->z ? *origin->z : 0.0);
    return {kind, BRepPrimAPI_MakeBox(corner, x, y, z).Shape(), own};
  }
  if (kind == "cylinder") {
    const double radius = required(part, "radius", xpath), height = required(part, "height", xpath);
    requirePositive(radius, "the radius", xpath);
    requirePositive(height, "the height", xpath);
    return {kind, cone(radius, radius, height), own};
  }
  if (kind == "cone" || kind == "frustum") {
    const double lower = required(part, "lowerRadius", xpath), height = required(part, "height", xpath);
    const double upper = schema::numberIn(part, "upperRadius", xpath).value_or(0.0);
    if (lower < 0.0 || upper < 0.0 || (lower == 0.0 && upper == 0.0))
      throw Error(ErrorCode::InvalidModel, "the radii must not be negative and one must be positive", {}, xpath);
    requirePositive(height, "the height", xpath);
    return {kind, cone(lower, upper, height), own};
  }
  if (kind == "ellipsoid") {
    const double x = required(part, "radiusX", xpath);
    const double y = schema::numberIn(part, "radiusY", xpath).value_or(x);
    const double z = schema::numberIn(part, "radiusZ", xpath).value_or(x);
    if (x <= 0.0 || y <= 0.0 || z <= 0.0) throw Error(ErrorCode::InvalidModel, "the radii must be positive", {}, xpath);
    // The unit sphere stretched by the three radii.
    return {kind, BRepPrimAPI_MakeSphere(1.0, revolutionAngle(part, xpath)).Shape(),
            own * Eigen::Scaling(Eigen::Vector3d(x, y, z))};
  }
  // A torus about the z axis.
  const double major = required(part, "majorRadius", xpath), minor = required(part, "minorRadius", xpath);
  requirePositive(major, "the major radius", xpath);
  requirePositive(minor, "the minor radius", xpath);
  if (minor >= major)
    throw Error(ErrorCode::InvalidModel, "the minor radius must be smaller than the major radius", {}, xpath);
  return {kind, BRepPrimAPI_MakeTorus(major, minor, revolutionAngle(part, xpath)).Shape(), own};
}

/// Every face of a shape named "<uid>/<kind> <n>".
NamedShape named(const TopoDS_Shape& shape, const std::string& name) {
  NamedShape result{shape, {}};
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next())
    result.faces.emplace_back(name, TopoDS::Face(face.Current()));
  return result;
}

}  // namespace

NamedShape elementGeometry(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                           const DOMElement& geometry, const std::string& xpath, const model::Transform& placement,
                           const std::string& uid) {
  const model::Transform frame = placement * transformationOf(geometry, xpath);
  std::vector<NamedShape> parts;
  const auto add = [&](const std::string& kind, std::size_t index, const std::function<NamedShape()>& build) {
    try {
      parts.push_back(build());
    } catch (const Error& error) {
      if (!error.cpacsPath().empty()) throw;
      throw Error(error.code(), "the " + kind + " " + std::to_string(index) + ": " + error.message(), {}, xpath);
    }
  };
  for (const char* kind : {"cuboid", "cylinder", "cone", "ellipsoid", "torus"}) {
    const std::string list = std::string(kind) == "torus" ? "tori" : std::string(kind) + "s";
    const auto items = listed(geometry, list, kind);
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::string partPath = xpath + "/" + list + "/" + kind + "[" + std::to_string(i + 1) + "]";
      add(kind, i + 1, [&] {
        const Part part = primitive(kind, *items[i], partPath);
        return transformedNamedShape(named(part.shape, uid + "/" + kind + " " + std::to_string(i + 1)),
                                     frame * part.transform);
      });
    }
  }
  // CPACS 3.5's element geometry: one part of each kind.
  for (const char* kind : {"parallelepiped", "frustum", "sphere", "boundingBox"})
    if (const DOMElement* item = xml::firstChild(geometry, kind))
      add(kind, 1, [&] {
        const Part part = primitive(kind, *item, xpath + "/" + kind);
        return transformedNamedShape(named(part.shape, uid + "/" + kind), frame * part.transform);
      });
  const auto shapes = listed(geometry, "multiSegmentShapes", "multiSegmentShape");
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const std::string partPath = xpath + "/multiSegmentShapes/multiSegmentShape[" + std::to_string(i + 1) + "]";
    add("multi-segment shape", i + 1, [&] {
      auto body = schema::readElement<schema::FuselageType>(*shapes[i], partPath);
      body->uID = uid + "/multi-segment shape " + std::to_string(i + 1);  // its loft's key
      return fuselages.bodySolid(configuration, *body, frame * transformationOf(*shapes[i], partPath));
    });
  }
  std::vector<const DOMElement*> files = listed(geometry, "externals", "external");
  if (const DOMElement* file = xml::firstChild(geometry, "genericGeometryComponent")) files.push_back(file);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string partPath = xml::pathOf(*files[i]);
    add("external file", i + 1, [&] {
      const DOMElement* link = xml::firstChild(*files[i], "linkToFile");
      if (link == nullptr) throw Error(ErrorCode::InvalidModel, "no linkToFile given", {}, partPath);
      const TopoDS_Shape shape =
          readExternalFile(configuration, xml::text(*link), xml::attribute(*link, "format"), partPath + "/linkToFile");
      return transformedNamedShape(named(shape, uid + "/external " + std::to_string(i + 1)),
                                   frame * transformationOf(*files[i], partPath));
    });
  }
  if (parts.empty()) throw NoShape("the element's geometry has no part: no shape", xpath);
  std::vector<const NamedShape*> built;
  for (const NamedShape& part : parts) built.push_back(&part);
  return compoundOfNamedShapes(built);
}

}  // namespace airshape::generic
