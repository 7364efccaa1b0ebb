#include "component_queries.h"

#include <algorithm>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/loop_area.h"
#include "airshape/query/arguments.h"
#include "intersection_curves.h"

namespace airshape::query {

namespace {

/// The component a query's uID argument (`name`) names; an error for any other uID.
const graph::Component& componentArgument(const Configuration& configuration, const Json& query, const char* name) {
  return configuration.components().named(stringArgument(query, name));
}

/// The shape of a component that has geometry: not the model, built, and not empty.
const TopoDS_Shape& measuredShape(const Configuration& configuration, const graph::Component& component) {
  const TopoDS_Shape& shape = configuration.shapes().shapeOf(configuration, component.uid);
  Bnd_Box box;
  if (!shape.IsNull()) BRepBndLib::Add(shape, box);
  if (box.IsVoid()) throw Error(ErrorCode::InvalidModel, "component '" + component.uid + "' has no geometry");
  return shape;
}

Json componentEntry(const graph::Component& component) {
  return {{"uid", component.uid}, {"type", component.typeName}};
}

/// Every component of the model queries address (the first model) that the reference
/// registers (QUERY-components §1), sorted by uID; with "all": true every component Airshape
/// knows (a plugin declares them `unlisted()`).
Json componentList(Configuration& configuration, const Json& query) {
  const bool all = query.contains("all") && query.at("all").is_boolean() && query.at("all").get<bool>();
  std::vector<const graph::Component*> listed;
  for (const graph::Component& component : configuration.components().components())
    if (component.model == 0 && !component.uid.empty() &&
        (all || (component.listed && configuration.components().leftOutReason(component).empty())))
      listed.push_back(&component);
  std::sort(listed.begin(), listed.end(), [](const auto* a, const auto* b) { return a->uid < b->uid; });
  Json list = Json::array();
  for (const graph::Component* component : listed) list.push_back(componentEntry(*component));
  return list;
}

/// The components directly inside one (its parts and what lies in it).
Json componentChildren(Configuration& configuration, const Json& query) {
  const std::string& parent = componentArgument(configuration, query, "uid").uid;
  Json children = Json::array();
  for (const graph::Component& component : configuration.components().components())
    if (component.parentUid == parent && !component.uid.empty()) children.push_back(componentEntry(component));
  return children;
}

Json componentType(Configuration& configuration, const Json& query) {
  return componentArgument(configuration, query, "uid").typeName;
}

Json componentVolume(Configuration& configuration, const Json& query) {
  return geometry::enclosedVolume(measuredShape(configuration, componentArgument(configuration, query, "uid")));
}

Json componentSurfaceArea(Configuration& configuration, const Json& query) {
  return geometry::areaOf(measuredShape(configuration, componentArgument(configuration, query, "uid")));
}

/// How many solids a shape holds.
int solidCount(const TopoDS_Shape& shape) {
  int count = 0;
  for (TopExp_Explorer solid(shape, TopAbs_SOLID); solid.More(); solid.Next()) ++count;
  return count;
}

/// The area of the component's section by an infinite plane: the faces the plane and the
/// shape have in common (none for a shape without solids). For one solid, from the closed
/// lines where the plane cuts it, without building the faces (OCCT's Boolean common also
/// splits every face of the solid the plane crosses: 1.3 s on a guided body of 800,000
/// knot spans); where a line does not close or the lines cross, by the common.
Json crossSectionArea(Configuration& configuration, const Json& query) {
  const TopoDS_Shape& shape = measuredShape(configuration, componentArgument(configuration, query, "uid"));
  const auto point = pointArgument(query, "point");
  const auto normal = pointArgument(query, "normal");
  const gp_Vec direction(normal[0], normal[1], normal[2]);
  if (direction.Magnitude() == 0.0) throw Error(ErrorCode::InvalidArgument, "the normal must not be zero");
  const gp_Pln plane(gp_Pnt(point[0], point[1], point[2]), gp_Dir(direction));
  if (solidCount(shape) == 1)
    if (const auto loops = planeSectionLoops(shape, plane))
      if (const auto area = geometry::areaInsideLoops(plane, *loops)) return *area;
  BRepAlgoAPI_Common common(shape, BRepBuilderAPI_MakeFace(plane).Face());
  if (!common.IsDone() || common.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the section of '" + stringArgument(query, "uid") + "' could not be computed");
  return geometry::areaOf(common.Shape());
}

/// The lines where two components' shapes meet (QUERY-components §4).
std::vector<TopoDS_Wire> linesOf(Configuration& configuration, const Json& query) {
  const graph::Component& first = componentArgument(configuration, query, "uid1");
  const graph::Component& second = componentArgument(configuration, query, "uid2");
  if (first.uid == second.uid)
    throw Error(ErrorCode::InvalidArgument, "uid1 and uid2 name the same component '" + first.uid + "'");
  return intersectionLines(measuredShape(configuration, first), measuredShape(configuration, second),
                           "'" + first.uid + "' and '" + second.uid + "'");
}

Json intersectionCount(Configuration& configuration, const Json& query) { return linesOf(configuration, query).size(); }

Json intersectionLength(Configuration& configuration, const Json& query) {
  double length = 0.0;
  for (const TopoDS_Wire& line : linesOf(configuration, query)) length += geometry::lengthOf(line);
  return length;
}

}  // namespace

void registerComponentQueries(QueryRegistry& registry) {
  registry.add({"component_list", "core",
                "[all] -> [{uid, type}] of the first model's components the reference registers, sorted by uID; "
                "all: true lists every one",
                componentList});
  registry.add({"component_children", "core",
                "uid -> [{uid, type}] of the components directly inside it (its parts and what lies in it)",
                componentChildren});
  registry.add({"component_type", "core", "uid -> the component's type (as its plugin declares it; the model: plane)",
                componentType});
  registry.add(
      {"component_volume", "core", "uid -> volume of the component's solids and closed shells", componentVolume});
  registry.add(
      {"component_surface_area", "core", "uid -> area of all faces of the component's shape", componentSurfaceArea});
  registry.add({"cross_section_area", "core",
                "uid, point, normal -> area of the component's section by the plane through point", crossSectionArea});
  registry.add(
      {"intersection_count", "core", "uid1, uid2 -> number of lines where the two shapes meet", intersectionCount});
  registry.add({"intersection_length", "core", "uid1, uid2 -> total length of those lines", intersectionLength});
}

}  // namespace airshape::query
