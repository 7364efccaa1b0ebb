#include "skin_lines.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <optional>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/ruled_crossing.h"
#include "airshape/geometry/skin_section.h"
#include "compounds.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "position_rays.h"

namespace airshape::structure {

namespace {

/// The skin face an edge lies on where the section names none (an edge along a seam between two
/// faces): the face nearest its middle.
TopoDS_Face faceUnder(const TopoDS_Edge& edge, const std::vector<TopoDS_Face>& faces) {
  BRepAdaptor_Curve curve(edge);
  const gp_Pnt middle = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
  const TopoDS_Vertex point = BRepBuilderAPI_MakeVertex(middle);
  TopoDS_Face nearest;
  double best = Precision::Infinite();
  for (const TopoDS_Face& face : faces) {
    Bnd_Box box;
    BRepBndLib::Add(face, box, false);
    if (box.IsOut(middle)) continue;
    BRepExtrema_DistShapeShape distance(point, face);
    if (distance.IsDone() && distance.Value() < best) {
      best = distance.Value();
      nearest = face;
    }
  }
  return nearest;
}

/// Where the tool faces meet the fuselage's skin, edge by edge with the skin face each lies on;
/// throws Error naming `where` when they do not meet.
std::vector<SkinEdge> onSkin(const FuselageFrame& fuselage, const std::vector<TopoDS_Face>& tools,
                             const std::string& where) {
  BRepAlgoAPI_Section section(compoundOf(fuselage.skinFaces()), compoundOf(tools), false);
  section.SetRunParallel(true);
  section.SetNonDestructive(true);  // the skin is shared, cached geometry
  section.Build();
  if (!section.IsDone() || section.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the line on the fuselage's skin cannot be found", {}, where);
  std::vector<SkinEdge> pieces;
  for (TopExp_Explorer edge(section.Shape(), TopAbs_EDGE); edge.More(); edge.Next()) {
    TopoDS_Shape face;
    const TopoDS_Edge& piece = TopoDS::Edge(edge.Current());
    if (!section.HasAncestorFaceOn1(piece, face))  // the tool met the skin along an edge of its faces
      face = faceUnder(piece, fuselage.skinFaces());
    pieces.push_back({piece, face.IsNull() ? TopoDS_Face() : TopoDS::Face(face)});
  }
  if (pieces.empty())
    throw Error(ErrorCode::InvalidModel, "the positions' rays do not meet the fuselage's skin", {}, where);
  return pieces;
}

/// The line where the rays of the spans meet the skin: straight from the skin, or by a section.
std::vector<SkinEdge> linesOnSkin(const FuselageFrame& fuselage, const std::vector<RaySpan>& spans,
                                  const std::vector<TopoDS_Face>& sweep, const std::string& where) {
  if (auto edges = raysOnSkin(fuselage, spans)) return *edges;
  return onSkin(fuselage, sweep, where);
}

NamedShape linesOf(const std::vector<SkinEdge>& pieces) {
  std::vector<TopoDS_Edge> edges;
  for (const SkinEdge& piece : pieces) edges.push_back(piece.edge);
  return edgesOf(compoundOf(edges));
}

}  // namespace

std::optional<std::vector<SkinEdge>> raysOnSkin(const FuselageFrame& fuselage, const std::vector<RaySpan>& spans) {
  const auto patches = geometry::skinPatches(compoundOf(fuselage.skinFaces()));
  if (!patches) return std::nullopt;
  const double tolerance = geometry::kTraceTolerance * fuselage.reach();
  std::vector<SkinEdge> edges;
  TopoDS_Vertex opening, previous;
  try {
    for (std::size_t k = 0; k < spans.size(); ++k) {
      const auto& [a, b] = spans[k];
      const gp_Pnt from = fuselage.toGlobal(a.origin), to = fuselage.toGlobal(b.origin);
      const geometry::RuledLines lines{from, to, gp_Vec(from, fuselage.toGlobal(a.origin.Translated(a.direction))),
                                       gp_Vec(to, fuselage.toGlobal(b.origin.Translated(b.direction))), true};
      const auto pieces = geometry::ruledCrossing(patches->patches, lines, tolerance);
      if (!pieces || !geometry::coversAllLines(*pieces)) return std::nullopt;
      for (std::size_t p = 0; p < pieces->size(); ++p) {
        const geometry::CrossingPiece& piece = (*pieces)[p];
        const geometry::Patch& patch = patches->patches[piece.patch];
        auto pointAt = [&](double t) {
          const gp_Pnt2d uv = piece.curve->Value(t);
          return patch.surface->Value(uv.X(), uv.Y());
        };
        auto near = [&](const TopoDS_Vertex& vertex, const gp_Pnt& point) {
          return !vertex.IsNull() && BRep_Tool::Pnt(vertex).Distance(point) <= 10.0 * tolerance;
        };
        const gp_Pnt start = pointAt(piece.points.front().t), end = pointAt(piece.points.back().t);
        const TopoDS_Vertex first = near(previous, start) ? previous : geometry::vertexWithin(start, 10.0 * tolerance);
        if (opening.IsNull()) opening = first;
        // A line that comes back to where it began (a frame all round) closes on its first vertex.
        const bool closing = k + 1 == spans.size() && p + 1 == pieces->size() && near(opening, end);
        const TopoDS_Vertex last = closing ? opening : geometry::vertexWithin(end, 10.0 * tolerance);
        BRepBuilderAPI_MakeEdge edge(piece.curve, patch.surface, first, last, piece.points.front().t,
                                     piece.points.back().t);
        if (!edge.IsDone()) return std::nullopt;
        TopoDS_Edge made = edge.Edge();
        if (!BRepLib::BuildCurve3d(made)) return std::nullopt;
        edges.push_back({made, patches->faces[piece.patch]});
        previous = last;
      }
    }
  } catch (const geometry::FoldedSkin&) {
    return std::nullopt;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
  return edges;
}

std::vector<SkinEdge> frameOnSkin(const Configuration& configuration, const tank::TankServices* tanks,
                                  const std::string& uid) {
  const auto frame = frameElementNamed(configuration, uid, tanks);
  const FuselageFrame fuselage =
      FuselageFrame::ofHost(configuration, frame.hostUid, frame.fuselage, frame.vesselPlacement);
  if (frame.node->framePosition.size() > 1)
    return linesOnSkin(fuselage, frameSpans(fuselage, *frame.node),
                       frameSweep(fuselage, *frame.node, fuselage.localReach()), frame.node->xpath);
  const gp_Pln station = fuselage.station(*frame.node);
  const double reach = fuselage.reach();
  return linesOnSkin(fuselage, ringSpans(fuselage, *frame.node),
                     {BRepBuilderAPI_MakeFace(station, -reach, reach, -reach, reach).Face()}, frame.node->xpath);
}

std::vector<SkinEdge> stringerOnSkin(const Configuration& configuration, const tank::TankServices* tanks,
                                     const std::string& uid) {
  const auto stringer = stringerElementNamed(configuration, uid, tanks);
  const FuselageFrame fuselage =
      FuselageFrame::ofHost(configuration, stringer.hostUid, stringer.fuselage, stringer.vesselPlacement);
  const StringerPath path(fuselage, *stringer.node);
  if (path.lastX() <= path.firstX())
    throw Error(ErrorCode::InvalidModel, "the stringer's positions lie at one station: it has no length", {},
                stringer.node->xpath);
  return linesOnSkin(fuselage, path.spans(path.firstX(), path.lastX()),
                     path.surface(fuselage, path.firstX(), path.lastX(), fuselage.localReach()), stringer.node->xpath);
}

NamedShape frameLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid) {
  return linesOf(frameOnSkin(configuration, tanks, uid));
}

NamedShape stringerLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid) {
  return linesOf(stringerOnSkin(configuration, tanks, uid));
}

}  // namespace airshape::structure
