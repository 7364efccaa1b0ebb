#include "intersection_curves.h"

#include <BRepAdaptor_CompCurve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cmath>
#include <optional>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/faces_near.h"
#include "airshape/geometry/tangent_contact.h"
#include "airshape/geometry/traced_section.h"
#include "airshape/query/arguments.h"

namespace airshape::query {

namespace {

constexpr double kDefaultDeflection = 1e-3;
constexpr double kChainingTolerance = 1e-6;
/// How closely traced section curves follow the true crossing, as a share of the two shapes' size.
constexpr double kTracingTolerance = 1e-9;
/// How close a plane face and a surface must come to touch: OCCT's own confusion distance.
constexpr double kContactTolerance = 1e-7;

/// Whether two lines are one: the same ends (either way round) and the same length.
bool sameLine(const TopoDS_Wire& a, const TopoDS_Wire& b) {
  TopoDS_Vertex a1, a2, b1, b2;
  TopExp::Vertices(a, a1, a2);
  TopExp::Vertices(b, b1, b2);
  if (a1.IsNull() || b1.IsNull()) return false;
  const auto near = [](const TopoDS_Vertex& p, const TopoDS_Vertex& q) {
    return BRep_Tool::Pnt(p).Distance(BRep_Tool::Pnt(q)) <= kChainingTolerance;
  };
  const bool sameEnds = (near(a1, b1) && near(a2, b2)) || (near(a1, b2) && near(a2, b1));
  const double lengthA = geometry::lengthOf(a), lengthB = geometry::lengthOf(b);
  return sameEnds && std::abs(lengthA - lengthB) <= 1e-9 * std::max(1.0, lengthA);
}

Json polyline(const TopoDS_Wire& wire, double deflection) {
  const BRepAdaptor_CompCurve curve(wire);
  GCPnts_QuasiUniformDeflection points(curve, deflection);
  if (!points.IsDone()) throw Error(ErrorCode::InvalidModel, "the intersection curve could not be discretised");
  Json line = Json::array();
  for (int i = 1; i <= points.NbPoints(); ++i) {
    const gp_Pnt p = points.Value(i);
    line.push_back({p.X(), p.Y(), p.Z()});
  }
  return line;
}

/// The edges where two shapes meet, by OCCT's Boolean section.
std::vector<TopoDS_Edge> sectionEdges(const TopoDS_Shape& first, const TopoDS_Shape& second, const std::string& names) {
  BRepAlgoAPI_Section section(first, second, false);
  section.Approximation(true);
  // With the curves on both faces OCCT checks the tolerance the section curves reached along
  // those curves; without them it projects points onto the (many-knotted) surfaces, which was
  // 60 % of a lifting surface's section with a body.
  section.ComputePCurveOn1(true);
  section.ComputePCurveOn2(true);
  section.SetRunParallel(true);     // the face pairs on every core: 2.4 times as fast on two
  section.SetNonDestructive(true);  // the components' shapes are shared, cached geometry
  section.Build();
  if (!section.IsDone() || section.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the intersection of " + names + " could not be computed");
  std::vector<TopoDS_Edge> edges;
  for (TopExp_Explorer explorer(section.Shape(), TopAbs_EDGE); explorer.More(); explorer.Next())
    edges.push_back(TopoDS::Edge(explorer.Current()));
  return edges;
}

/// The edges joined end to end into lines.
std::vector<TopoDS_Wire> chained(const std::vector<TopoDS_Edge>& edges) {
  Handle(TopTools_HSequenceOfShape) held = new TopTools_HSequenceOfShape;
  for (const TopoDS_Edge& edge : edges) held->Append(edge);
  Handle(TopTools_HSequenceOfShape) wires = new TopTools_HSequenceOfShape;
  if (!held->IsEmpty()) ShapeAnalysis_FreeBounds::ConnectEdgesToWires(held, kChainingTolerance, false, wires);
  std::vector<TopoDS_Wire> lines;
  for (int i = 1; i <= wires->Length(); ++i) lines.push_back(TopoDS::Wire(wires->Value(i)));
  return lines;
}

/// Whether a line closes on itself.
bool closed(const TopoDS_Wire& wire) {
  TopoDS_Vertex start, end;
  TopExp::Vertices(wire, start, end);
  if (start.IsNull() || end.IsNull()) return BRep_Tool::IsClosed(wire);
  return BRep_Tool::Pnt(start).Distance(BRep_Tool::Pnt(end)) <= kChainingTolerance;
}

/// The lines where a shape of ruled faces meets the other's skin, traced along the rulings
/// (geometry/traced_section.h): a tenth of the Boolean section's time on a lifting surface and a body,
/// whose surface-surface walking over skins of many knots dominates. Two closed solids meet in
/// closed lines: nothing unless every line closes, and nothing where the tracing does not apply
/// (then the Boolean section answers).
std::optional<std::vector<TopoDS_Wire>> tracedLines(const TopoDS_Shape& ruled, const TopoDS_Shape& skin) {
  Bnd_Box box;
  BRepBndLib::Add(ruled, box, false);
  BRepBndLib::Add(skin, box, false);
  if (box.IsVoid()) return std::nullopt;
  const std::optional<std::vector<TopoDS_Edge>> edges =
      geometry::tracedSection(ruled, skin, kTracingTolerance * std::sqrt(box.SquareExtent()));
  if (!edges) return std::nullopt;
  std::vector<TopoDS_Wire> lines = chained(*edges);
  if (!std::all_of(lines.begin(), lines.end(), closed)) return std::nullopt;
  return lines;
}

/// The boxes of a shape's faces, each widened by a ten-thousandth of the shape's size (room
/// for rounding): tighter round a thin part than the shape's one box.
geometry::Region faceBoxes(const TopoDS_Shape& shape) {
  Bnd_Box whole;
  BRepBndLib::Add(shape, whole, false);
  if (whole.IsVoid()) return {};
  const double margin = 1e-4 * std::sqrt(whole.SquareExtent());
  geometry::Region boxes;
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next()) {
    Bnd_Box box;
    BRepBndLib::Add(face.Current(), box, false);
    box.Enlarge(margin);
    boxes.push_back(box);
  }
  return boxes;
}

/// Each shape's faces cut down to where the other's faces are (geometry/faces_near.h): so that
/// the Boolean section samples a thin part's few faces against the part of a revolved cowl beside
/// it, not its whole circumference (26 s -> 6 s on one shared file, docs/performance.md).
std::pair<TopoDS_Shape, TopoDS_Shape> partsWhereTheyMayMeet(const TopoDS_Shape& first, const TopoDS_Shape& second) {
  return {geometry::facesNear(first, faceBoxes(second)), geometry::facesNear(second, faceBoxes(first))};
}

/// The lines' edges.
std::vector<TopoDS_Edge> edgesOf(const std::vector<TopoDS_Wire>& lines) {
  std::vector<TopoDS_Edge> edges;
  for (const TopoDS_Wire& line : lines)
    for (TopExp_Explorer explorer(line, TopAbs_EDGE); explorer.More(); explorer.Next())
      edges.push_back(TopoDS::Edge(explorer.Current()));
  return edges;
}

}  // namespace

std::vector<TopoDS_Wire> intersectionLines(const TopoDS_Shape& first, const TopoDS_Shape& second,
                                           const std::string& names) {
  std::optional<std::vector<TopoDS_Wire>> wires = tracedLines(first, second);
  if (!wires) wires = tracedLines(second, first);
  if (!wires) {
    const auto [nearFirst, nearSecond] = partsWhereTheyMayMeet(first, second);
    wires = chained(sectionEdges(nearFirst, nearSecond, names));
  }
  // A root laid on a body's side touches it along a line the section misses.
  if (const auto touching = geometry::withTangentContacts(edgesOf(*wires), first, second, kContactTolerance))
    wires = chained(*touching);
  std::vector<TopoDS_Wire> lines;
  for (const TopoDS_Wire& wire : *wires)
    if (std::none_of(lines.begin(), lines.end(), [&](const TopoDS_Wire& kept) { return sameLine(kept, wire); }))
      lines.push_back(wire);
  return lines;
}

std::optional<std::vector<TopoDS_Wire>> planeSectionLoops(const TopoDS_Shape& shape, const gp_Pln& plane) {
  BRepAlgoAPI_Section section(shape, plane, false);
  section.Approximation(true);  // the curves a Boolean common would trim the plane with
  section.ComputePCurveOn1(true);
  section.ComputePCurveOn2(true);
  section.SetNonDestructive(true);  // the components' shapes are shared, cached geometry
  section.Build();
  if (!section.IsDone() || section.HasErrors()) return std::nullopt;
  std::vector<TopoDS_Edge> edges;
  for (TopExp_Explorer explorer(section.Shape(), TopAbs_EDGE); explorer.More(); explorer.Next())
    edges.push_back(TopoDS::Edge(explorer.Current()));
  std::vector<TopoDS_Wire> loops = chained(edges);
  if (!std::all_of(loops.begin(), loops.end(), closed)) return std::nullopt;
  return loops;
}

Json intersectionCurves(Configuration& configuration, const Json& query) {
  const ComponentShapes& shapes = configuration.shapes();
  const TopoDS_Shape& first = shapes.shapeOf(configuration, stringArgument(query, "uid"));
  const std::string other = stringArgument(query, "other");
  const bool mirrored = query.contains("other_mirrored") && query.at("other_mirrored").is_boolean() &&
                        query.at("other_mirrored").get<bool>();
  const TopoDS_Shape& second =
      mirrored ? shapes.mirroredShapeOf(configuration, other).shape : shapes.shapeOf(configuration, other);
  const double deflection = query.contains("deflection") ? numberArgument(query, "deflection") : kDefaultDeflection;
  if (!(deflection > 0)) throw Error(ErrorCode::InvalidArgument, "deflection must be positive");

  Json curves = Json::array();
  for (const TopoDS_Wire& line :
       intersectionLines(first, second, "'" + stringArgument(query, "uid") + "' and '" + other + "'"))
    curves.push_back(polyline(line, deflection));
  return curves;
}

}  // namespace airshape::query
