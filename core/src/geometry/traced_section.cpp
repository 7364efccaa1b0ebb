#include "airshape/geometry/traced_section.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAPI_IntSS.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/geometry/bspline_patch.h"
#include "airshape/geometry/ruled_crossing.h"

namespace airshape::geometry {

namespace {

/// The patch's rulings where it is a ruled surface (degree 1 with two rows of
/// poles one way); nothing otherwise.
std::optional<RulingSegments> rulingsOf(const Patch& patch) {
  const Handle(Geom_BSplineSurface)& surface = patch.surface;
  if (surface->VDegree() == 1 && surface->NbVPoles() == 2)
    return RulingSegments{surface->VIso(patch.v0), surface->VIso(patch.v1), patch.u0, patch.u1};
  if (surface->UDegree() == 1 && surface->NbUPoles() == 2)
    return RulingSegments{surface->UIso(patch.u0), surface->UIso(patch.u1), patch.v0, patch.v1};
  return std::nullopt;
}

bool isPlane(const TopoDS_Face& face) {
  return GeomAdaptor_Surface(BRep_Tool::Surface(face)).GetType() == GeomAbs_Plane;
}

/// Whether untrimmed patches meet a plane face nowhere inside it, given that they do not cross
/// the face's boundary: then each line where a patch meets the face's plane lies wholly inside
/// the face or wholly outside, and one point of each tells. Only patches whose poles' box
/// reaches the face are intersected with its plane (OCCT's Boolean section would also meet the
/// face's edges, an airfoil of many knots, with every face: ten times as slow).
bool missesPlaneFace(const std::vector<Patch>& patches, const TopoDS_Face& face) {
  const Handle(Geom_Surface) plane = BRep_Tool::Surface(face);
  Bnd_Box faceBox;
  BRepBndLib::Add(face, faceBox, false);
  const double tolerance = std::max(BRep_Tool::MaxTolerance(face, TopAbs_EDGE), Precision::Confusion());
  faceBox.Enlarge(tolerance);
  for (const Patch& patch : patches) {
    if (poleBox(patch).IsOut(faceBox)) continue;
    GeomAPI_IntSS crossing(plane, patch.surface, tolerance);
    if (!crossing.IsDone()) return false;
    for (int i = 1; i <= crossing.NbLines(); ++i) {
      const Handle(Geom_Curve) line = crossing.Line(i);
      const gp_Pnt middle = line->Value(0.5 * (line->FirstParameter() + line->LastParameter()));
      double u = 0, v = 0;
      GeomAPI_ProjectPointOnSurf(middle, plane).LowerDistanceParameters(u, v);
      if (BRepClass_FaceClassifier(face, gp_Pnt2d(u, v), tolerance).State() != TopAbs_OUT) return false;
    }
  }
  return true;
}

/// Whether every edge's ends meet another edge's end: the lines close.
bool closedLines(const std::vector<TopoDS_Edge>& edges, double tolerance) {
  std::vector<gp_Pnt> ends;
  for (const TopoDS_Edge& edge : edges) {
    const BRepAdaptor_Curve curve(edge);
    ends.push_back(curve.Value(curve.FirstParameter()));
    ends.push_back(curve.Value(curve.LastParameter()));
  }
  for (std::size_t i = 0; i < ends.size(); ++i) {
    bool met = false;
    for (std::size_t j = 0; j < ends.size() && !met; ++j) met = j != i && ends[i].Distance(ends[j]) <= tolerance;
    if (!met) return false;
  }
  return true;
}

/// The edge along a piece of crossing on its skin face.
std::optional<TopoDS_Edge> edgeAlong(const CrossingPiece& piece, const Patch& patch, double tolerance) {
  const double first = piece.points.front().t, last = piece.points.back().t;
  BRepBuilderAPI_MakeEdge edge(piece.curve, patch.surface, first, last);
  if (!edge.IsDone()) return std::nullopt;
  TopoDS_Edge made = edge.Edge();
  if (!BRepLib::BuildCurve3d(made, tolerance)) return std::nullopt;
  return made;
}

}  // namespace

std::optional<std::vector<TopoDS_Edge>> tracedSection(const TopoDS_Shape& ruled, const TopoDS_Shape& skin,
                                                      double tolerance) {
  // The skin's curved faces must be patches; its planes (a body's end caps) and the ruled
  // shape's planes (a lifting surface's root and tip) are checked to be met nowhere.
  std::vector<Patch> patches, ruledPatches;
  std::vector<TopoDS_Face> skinPlanes, ruledPlanes;
  for (TopExp_Explorer explorer(skin, TopAbs_FACE); explorer.More(); explorer.Next()) {
    const TopoDS_Face& face = TopoDS::Face(explorer.Current());
    if (isPlane(face)) {
      skinPlanes.push_back(face);
    } else if (const std::optional<Patch> patch = patchOf(face)) {
      patches.push_back(*patch);
    } else {
      return std::nullopt;
    }
  }
  Bnd_Box skinBox;
  BRepBndLib::Add(skin, skinBox, false);
  std::vector<TopoDS_Edge> edges;
  for (TopExp_Explorer explorer(ruled, TopAbs_FACE); explorer.More(); explorer.Next()) {
    const TopoDS_Face& face = TopoDS::Face(explorer.Current());
    if (isPlane(face)) {
      ruledPlanes.push_back(face);
      continue;
    }
    const std::optional<Patch> patch = patchOf(face);
    if (!patch) return std::nullopt;
    ruledPatches.push_back(*patch);
    Bnd_Box faceBox;
    BRepBndLib::Add(face, faceBox, false);
    if (faceBox.IsOut(skinBox)) continue;
    // A ruled face along its rulings, another along its v-curves (a guided lifting surface's faces run
    // along the span in v): each must meet the skin at most once. Where those meet it nowhere
    // although the face reaches it, its curves the other way may: a blunt trailing edge is ruled
    // across its thickness, nearly along its crossing with a body.
    std::optional<std::vector<CrossingPiece>> pieces;
    try {
      const std::optional<RulingSegments> rulings = rulingsOf(*patch);
      pieces = rulings ? ruledCrossing(patches, *rulings, tolerance)
                       : ruledCrossing(patches, PatchCurves{*patch}, tolerance);
      const bool rulingsAlongV = !rulings || patch->surface->VDegree() == 1;  // as rulingsOf takes them
      if (pieces && pieces->empty()) pieces = ruledCrossing(patches, PatchCurves{*patch, rulingsAlongV}, tolerance);
    } catch (const FoldedSkin&) {
      return std::nullopt;
    }
    if (!pieces) return std::nullopt;
    for (const CrossingPiece& piece : *pieces) {
      const std::optional<TopoDS_Edge> edge = edgeAlong(piece, patches[piece.patch], tolerance);
      if (!edge) return std::nullopt;
      edges.push_back(*edge);
    }
  }
  // A line that crossed onto a plane face would end where it leaves the traced faces: closed
  // lines cross no plane face's boundary, so a plane face is met, if at all, in lines of its own.
  if (!closedLines(edges, 100.0 * tolerance)) return std::nullopt;
  for (const TopoDS_Face& plane : ruledPlanes)
    if (!missesPlaneFace(patches, plane)) return std::nullopt;
  for (const TopoDS_Face& plane : skinPlanes)
    if (!missesPlaneFace(ruledPatches, plane)) return std::nullopt;
  return edges;
}

}  // namespace airshape::geometry
