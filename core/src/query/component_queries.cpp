#include "component_queries.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Bnd_Box.hxx>
#include <ElSLib.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt2d.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/model/primary_model.h"
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
/// knows (spoilers, frames, CPACS 3.5 tanks, ...).
Json componentList(Configuration& configuration, const Json& query) {
  const bool all = query.contains("all") && query.at("all").is_boolean() && query.at("all").get<bool>();
  std::vector<const graph::Component*> listed;
  for (const graph::Component& component : configuration.components().components())
    if (component.model == 0 && !component.uid.empty() &&
        (all || (component.listed && !model::leftOut(configuration, component))))
      listed.push_back(&component);
  std::sort(listed.begin(), listed.end(), [](const auto* a, const auto* b) { return a->uid < b->uid; });
  Json list = Json::array();
  for (const graph::Component* component : listed) list.push_back(componentEntry(*component));
  return list;
}

/// The components directly inside one (its segments, component segments, devices, spars, ...).
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

/// Points along a closed line in the plane's own 2D coordinates: 32 per edge.
std::vector<gp_Pnt2d> outlineIn(const gp_Pln& plane, const TopoDS_Wire& loop) {
  constexpr int kPointsPerEdge = 32;
  std::vector<gp_Pnt2d> outline;
  for (TopExp_Explorer explorer(loop, TopAbs_EDGE); explorer.More(); explorer.Next()) {
    const BRepAdaptor_Curve edge(TopoDS::Edge(explorer.Current()));
    for (int i = 0; i < kPointsPerEdge; ++i) {
      const gp_Pnt p =
          edge.Value(edge.FirstParameter() + (edge.LastParameter() - edge.FirstParameter()) * i / kPointsPerEdge);
      double x, y;
      ElSLib::Parameters(plane, p, x, y);
      outline.emplace_back(x, y);
    }
  }
  return outline;
}

/// Whether a point lies inside a closed polygon (crossings of a ray along +x).
bool inside(const gp_Pnt2d& point, const std::vector<gp_Pnt2d>& polygon) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const gp_Pnt2d &a = polygon[i], &b = polygon[j];
    if ((a.Y() > point.Y()) != (b.Y() > point.Y()) &&
        point.X() < a.X() + (b.X() - a.X()) * (point.Y() - a.Y()) / (b.Y() - a.Y()))
      in = !in;
  }
  return in;
}

/// Which side of the line from a to b the point c lies on: +1, -1, or 0 on it.
int sideOf(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& c) {
  const double cross = (b.X() - a.X()) * (c.Y() - a.Y()) - (b.Y() - a.Y()) * (c.X() - a.X());
  return cross > 0.0 ? 1 : (cross < 0.0 ? -1 : 0);
}

/// Whether two segments cross at a point inside both.
bool crossing(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& c, const gp_Pnt2d& d) {
  return sideOf(a, b, c) * sideOf(a, b, d) < 0 && sideOf(c, d, a) * sideOf(c, d, b) < 0;
}

/// Whether the outlines cross themselves or each other: then they bound no regions one
/// inside another (a solid that passes through itself).
bool anyCrossing(const std::vector<std::vector<gp_Pnt2d>>& outlines) {
  struct Segment {
    std::size_t outline, index;
    gp_Pnt2d from, to;
  };
  std::vector<Segment> segments;
  for (std::size_t k = 0; k < outlines.size(); ++k)
    for (std::size_t i = 0; i < outlines[k].size(); ++i)
      segments.push_back({k, i, outlines[k][i], outlines[k][(i + 1) % outlines[k].size()]});
  const auto low = [](const Segment& s) { return std::min(s.from.X(), s.to.X()); };
  const auto high = [](const Segment& s) { return std::max(s.from.X(), s.to.X()); };
  // Swept along x: a segment meets only those that start before it ends.
  std::sort(segments.begin(), segments.end(), [&](const Segment& a, const Segment& b) { return low(a) < low(b); });
  for (std::size_t m = 0; m < segments.size(); ++m)
    for (std::size_t n = m + 1; n < segments.size() && low(segments[n]) <= high(segments[m]); ++n) {
      const Segment &s = segments[m], &t = segments[n];
      const std::size_t size = outlines[s.outline].size();
      const bool neighbours =
          s.outline == t.outline && ((s.index + 1) % size == t.index || (t.index + 1) % size == s.index);
      if (!neighbours && crossing(s.from, s.to, t.from, t.to)) return true;
    }
  return false;
}

/// The area a solid's closed section lines enclose: each line's own area (Green's theorem,
/// exact per knot span), added where the line lies inside an even number of the others and
/// taken off where inside an odd number (the hole of a ring). Nothing where the lines cross
/// themselves or each other.
std::optional<double> areaInside(const gp_Pln& plane, const std::vector<TopoDS_Wire>& loops) {
  std::vector<std::vector<gp_Pnt2d>> outlines;
  for (const TopoDS_Wire& loop : loops) outlines.push_back(outlineIn(plane, loop));
  if (anyCrossing(outlines)) return std::nullopt;
  double area = 0.0;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    int depth = 0;
    for (std::size_t j = 0; j < loops.size(); ++j)
      if (j != i && !outlines[i].empty() && inside(outlines[i].front(), outlines[j])) ++depth;
    const double own = std::abs(geometry::signedAreaEnclosed(loops[i], plane.Axis().Direction()));
    area += depth % 2 == 0 ? own : -own;
  }
  return area;
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
/// splits every face of the solid the plane crosses: 1.3 s on a guided fuselage of 800,000
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
      if (const auto area = areaInside(plane, *loops)) return *area;
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
                "uid -> [{uid, type}] of the components directly inside it (segments, devices, spars, ...)",
                componentChildren});
  registry.add(
      {"component_type", "core", "uid -> the component's type (wing, wing_segment, plane, ...)", componentType});
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
