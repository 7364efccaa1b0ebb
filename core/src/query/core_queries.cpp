#include "airshape/query/core_queries.h"

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <tuple>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/model/symmetry.h"
#include "airshape/query/arguments.h"
#include "airshape/query/box_answer.h"
#include "component_queries.h"
#include "intersection_curves.h"

namespace airshape::query {

namespace {

/// The box of the mirror image about a coordinate plane: the box mirrored.
Bnd_Box mirrored(const Bnd_Box& box, const std::string& symmetry) {
  double x1, y1, z1, x2, y2, z2;
  box.Get(x1, y1, z1, x2, y2, z2);
  if (symmetry == "x-z") std::tie(y1, y2) = std::make_pair(-y2, -y1);
  if (symmetry == "x-y") std::tie(z1, z2) = std::make_pair(-z2, -z1);
  if (symmetry == "y-z") std::tie(x1, x2) = std::make_pair(-x2, -x1);
  Bnd_Box result;
  result.Update(x1, y1, z1, x2, y2, z2);
  return result;
}

/// The tight box of the whole configuration, mirrored halves included: the components that
/// count in it (QUERY-components §7) and that a plugin builds.
Bnd_Box configurationBox(Configuration& configuration) {
  Bnd_Box all;
  for (const auto& component : configuration.components().components()) {
    if (!component.inConfigurationBox || !configuration.components().leftOutReason(component).empty() ||
        configuration.shapes().find(component.nodeType) == nullptr)
      continue;
    Bnd_Box box;
    try {
      box = tightBox(configuration.shapes().shapeOf(configuration, component.uid));
    } catch (const NoShape&) {
      continue;  // as the reference leaves it out
    }
    all.Add(box);
    const std::string symmetry = model::resolvedSymmetry(configuration, component.uid);
    if (symmetry != "none") all.Add(mirrored(box, symmetry));
  }
  if (all.IsVoid()) throw Error(ErrorCode::NotImplemented, "no builder yet for any component of the configuration");
  return all;
}

Json boundingBox(Configuration& configuration, const Json& query) {
  if (query.contains("uid"))
    return boxAnswer(tightBox(configuration.shapes().shapeOf(configuration, stringArgument(query, "uid"))));
  return boxAnswer(configurationBox(configuration));
}

Json configurationLength(Configuration& configuration, const Json&) {
  double xMin, yMin, zMin, xMax, yMax, zMax;
  configurationBox(configuration).Get(xMin, yMin, zMin, xMax, yMax, zMax);
  return xMax - xMin;
}

}  // namespace

/// The named faces of a component's solid (or its mirrored half) with their areas and
/// centres, in the builder's order.
Json componentFaces(Configuration& configuration, const Json& query) {
  const std::string uid = stringArgument(query, "uid");
  const bool mirrored =
      query.contains("mirrored") && query.at("mirrored").is_boolean() && query.at("mirrored").get<bool>();
  const NamedShape& shape = mirrored ? configuration.shapes().mirroredShapeOf(configuration, uid)
                                     : configuration.shapes().namedShapeOf(configuration, uid);
  Json faces = Json::array();
  for (const auto& [name, face] : shape.faces) {
    GProp_GProps properties;
    BRepGProp::SurfaceProperties(face, properties);
    const gp_Pnt centre = properties.CentreOfMass();
    faces.push_back(
        {{"name", name}, {"area", geometry::areaOf(face)}, {"centre", {centre.X(), centre.Y(), centre.Z()}}});
  }
  return faces;
}

/// Turns a build option on or off for the rest of the session, answering what it was before.
Json setOption(Configuration& configuration, const Json& query) {
  const std::string name = stringArgument(query, "name");
  const bool on = booleanArgument(query, "on");
  const bool was = configuration.option(name);
  configuration.setOption(name, on);
  return {{"name", name}, {"on", on}, {"was", was}};
}

void registerCoreQueries(QueryRegistry& registry) {
  registry.add({"set_option", "core",
                "name, on -> {name, on, was}: turns a build option (duct_cutouts) on or off for the rest of the "
                "session; what it changes is rebuilt",
                setOption});
  registry.add({"bounding_box", "core",
                "[uid] -> {min, max}: tight box of a component, or of the whole configuration with mirrored halves",
                boundingBox});
  registry.add({"configuration_length", "core",
                "-> x extent of the configuration's tight box (bounding_box without uid)", configurationLength});
  registry.add({"component_faces", "core",
                "uid, [mirrored] -> [{name, area, centre}]: the named faces of a component's solid or mirrored half",
                componentFaces});
  registry.add({"intersection_curves", "core",
                "uid, other, [other_mirrored], [deflection] -> [[[x,y,z], ...], ...]: where two solids meet, "
                "as polylines",
                intersectionCurves});
  registerComponentQueries(registry);
}

}  // namespace airshape::query
