#include "airshape/geometry/brep_building.h"

#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Line.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Dir2d.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt2d.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/skinning.h"

namespace airshape::geometry {

namespace {

constexpr double kTolerance = 1e-7;
constexpr double kSewingTolerance = 1e-6;
/// A solid enclosing less than this fraction of its box diagonal cubed encloses nothing.
constexpr double kEmptyVolume = 1e-12;
/// A profile thinner on average (its area over its box diagonal) than this many sewing
/// tolerances encloses nothing: its cap would be a face whose edges touch.
constexpr double kThinnest = 10.0;

/// The plane through every pole of the curves (their least-squares plane) when they all lie
/// on it within kTolerance; nothing otherwise.
std::optional<gp_Pln> planeOfPoles(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  std::vector<Eigen::Vector3d> poles;
  for (const auto& curve : curves)
    for (int i = 1; i <= curve->NbPoles(); ++i)
      poles.emplace_back(curve->Pole(i).X(), curve->Pole(i).Y(), curve->Pole(i).Z());
  if (poles.size() < 3) return std::nullopt;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : poles) centre += p;
  centre /= static_cast<double>(poles.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const auto& p : poles) spread += (p - centre) * (p - centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(spread);
  if (axes.info() != Eigen::Success || !(axes.eigenvalues()(1) > 0.0)) return std::nullopt;  // a line or a point
  const Eigen::Vector3d normal = axes.eigenvectors().col(0);  // the direction of least spread
  for (const auto& p : poles)
    if (std::abs((p - centre).dot(normal)) > kTolerance) return std::nullopt;
  return gp_Pln(gp_Pnt(centre.x(), centre.y(), centre.z()), gp_Dir(normal.x(), normal.y(), normal.z()));
}

/// The planar face on a closed wire, sharing its edges. A B-spline lies in a plane exactly
/// when its poles do, so the plane through the poles spares OCCT's search for one (a fifth
/// of building a wing), and the plane's normal is turned so that the wire runs anticlockwise
/// about it, which spares OCCT's classification of the face's inside (another sixth); other
/// edges and near-planar wires are left to OCCT, which decides as before.
TopoDS_Face planarFaceOn(const TopoDS_Wire& wire) {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (TopExp_Explorer edges(wire, TopAbs_EDGE); edges.More(); edges.Next()) {
    double first, last;
    const auto curve =
        Handle(Geom_BSplineCurve)::DownCast(BRep_Tool::Curve(TopoDS::Edge(edges.Current()), first, last));
    if (curve.IsNull()) return BRepBuilderAPI_MakeFace(wire, true).Face();
    curves.push_back(curve);
  }
  Bnd_Box poles;
  for (const auto& curve : curves)
    for (int i = 1; i <= curve->NbPoles(); ++i) poles.Add(curve->Pole(i));
  const double enclosesNothing =
      kThinnest * kSewingTolerance * (poles.IsVoid() ? 0.0 : std::sqrt(poles.SquareExtent()));
  std::optional<gp_Pln> plane = planeOfPoles(curves);
  TopoDS_Face face;
  double area = 0.0;
  if (plane) {
    area = signedAreaEnclosed(wire, plane->Axis().Direction());
    if (area < 0.0) plane = gp_Pln(plane->Location(), plane->Axis().Direction().Reversed());
    BRepBuilderAPI_MakeFace onPlane(*plane, wire, false);
    if (onPlane.IsDone()) face = onPlane.Face();
  } else {
    BRepBuilderAPI_MakeFace found(wire, true);
    if (found.IsDone()) face = found.Face();
    if (!face.IsNull()) area = areaOf(face);
  }
  if (face.IsNull()) throw Error(ErrorCode::InvalidModel, "a profile is not planar, so no planar cap closes it");
  // A profile flattened to a line (scaled to no thickness or chord) may still bound a valid
  // face of no area (its edges apart); where its edges touch, no face closes it.
  if (std::abs(area) <= enclosesNothing && !BRepCheck_Analyzer(face).IsValid())
    throw Error(ErrorCode::InvalidModel, "a profile encloses no area (scaled to no thickness?)");
  return face;
}

/// The cap turned, where needed, so that it runs each of its edges against the side face
/// that shares it (a closed shell uses every edge once each way).
TopoDS_Face facingTheSides(TopoDS_Face cap, const TopTools_IndexedDataMapOfShapeListOfShape& facesOfEdges) {
  for (TopExp_Explorer edges(cap, TopAbs_EDGE); edges.More(); edges.Next()) {
    const TopoDS_Shape& edge = edges.Current();
    if (!facesOfEdges.Contains(edge))
      throw Error(ErrorCode::InvalidModel, "the ruled skin does not end on its profiles' edges");
    const TopoDS_Shape& side = facesOfEdges.FindFromKey(edge).First();
    for (TopExp_Explorer sideEdges(side, TopAbs_EDGE); sideEdges.More(); sideEdges.Next())
      if (sideEdges.Current().IsSame(edge))
        return sideEdges.Current().Orientation() == edge.Orientation() ? TopoDS::Face(cap.Reversed()) : cap;
  }
  return cap;
}

/// The solid turned so that its faces point outwards (Boolean operations then see its
/// inside); throws Error when it encloses no volume (a segment of zero length or thickness).
TopoDS_Solid outwards(TopoDS_Solid solid) {
  const double volume = roughSignedVolumeOf(solid);
  // The solid's scale: the box of its vertices costs next to nothing (the whole solid's box
  // is taken where the vertices all coincide).
  Bnd_Box box;
  for (TopExp_Explorer vertices(solid, TopAbs_VERTEX); vertices.More(); vertices.Next())
    box.Add(BRep_Tool::Pnt(TopoDS::Vertex(vertices.Current())));
  if (box.IsVoid() || box.SquareExtent() == 0.0) BRepBndLib::Add(solid, box);
  const double size = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
  if (std::abs(volume) <= kEmptyVolume * size * size * size)
    throw Error(ErrorCode::InvalidModel, "the faces enclose no volume (a segment of zero length or thickness?)");
  if (volume < 0) solid.Reverse();
  return solid;
}

}  // namespace

Handle(Geom_BSplineCurve) transformed(const Handle(Geom_BSplineCurve) & curve, const Eigen::Affine3d& transform) {
  Handle(Geom_BSplineCurve) moved = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  for (int i = 1; i <= moved->NbPoles(); ++i) {
    const gp_Pnt& p = moved->Pole(i);
    const Eigen::Vector3d q = transform * Eigen::Vector3d(p.X(), p.Y(), p.Z());
    moved->SetPole(i, gp_Pnt(q.x(), q.y(), q.z()));
  }
  return moved;
}

Handle(Geom_BSplineCurve) straightLine(const gp_Pnt& a, const gp_Pnt& b) {
  TColgp_Array1OfPnt poles(1, 2);
  poles(1) = a;
  poles(2) = b;
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0.0;
  knots(2) = 1.0;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(2);
  return new Geom_BSplineCurve(poles, knots, multiplicities, 1);
}

TopoDS_Face ruledFace(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & second) {
  const std::vector<double> sites = {0.0, 1.0};
  const auto surface = skinCurves({first, second}, sites, skinningSpace(sites, 1, false));
  return BRepBuilderAPI_MakeFace(surface, kTolerance).Face();
}

TopoDS_Face planarFace(const std::vector<Handle(Geom_BSplineCurve)>& boundary) {
  BRepBuilderAPI_MakeWire wire;
  for (const auto& curve : boundary) wire.Add(BRepBuilderAPI_MakeEdge(curve).Edge());
  if (!wire.IsDone()) throw Error(ErrorCode::InvalidModel, "the boundary curves do not join into a wire");
  return planarFaceOn(wire.Wire());
}

TopoDS_Shape sewnSolid(const std::vector<TopoDS_Face>& faces, std::vector<TopoDS_Face>* sewnFaces) {
  BRepBuilderAPI_Sewing sewing(kSewingTolerance);
  for (const TopoDS_Face& face : faces)
    if (!face.IsNull()) sewing.Add(face);
  sewing.Perform();
  TopExp_Explorer shells(sewing.SewedShape(), TopAbs_SHELL);
  if (!shells.More()) throw Error(ErrorCode::InvalidModel, "the faces do not close into a solid");
  const TopoDS_Solid solid = outwards(BRepBuilderAPI_MakeSolid(TopoDS::Shell(shells.Current())).Solid());
  if (sewnFaces) {
    sewnFaces->clear();
    for (const TopoDS_Face& face : faces)
      sewnFaces->push_back(face.IsNull() || !sewing.IsModified(face) ? face : TopoDS::Face(sewing.Modified(face)));
  }
  return solid;
}

namespace {

/// A closed loop of curves joined end to end, as topology: edge k on curve k, the vertex
/// where the loop enters edge k, and the wire running round.
struct Loop {
  std::vector<TopoDS_Edge> edges;
  std::vector<TopoDS_Vertex> entries;
  TopoDS_Wire wire;
};

bool meets(const gp_Pnt& a, const gp_Pnt& b) { return a.Distance(b) <= kSewingTolerance; }
gp_Pnt entryOf(const Geom_BSplineCurve& curve, bool forward) { return forward ? curve.StartPoint() : curve.EndPoint(); }
gp_Pnt exitOf(const Geom_BSplineCurve& curve, bool forward) { return forward ? curve.EndPoint() : curve.StartPoint(); }

/// Whether a loop can run the curves in these directions: each entered where the one before
/// left, and the last leaving where the first is entered.
bool runsRound(const std::vector<Handle(Geom_BSplineCurve)>& curves, const std::vector<bool>& forward) {
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const std::size_t next = (k + 1) % curves.size();
    if (!meets(exitOf(*curves[k], forward[k]), entryOf(*curves[next], forward[next]))) return false;
  }
  return true;
}

/// The directions in which a loop runs curves joined end to end: the first towards the
/// second, each next one onwards from where the one before ended. Throws Error when they do
/// not join or close.
std::vector<bool> directionsOf(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  const std::size_t n = curves.size();
  std::vector<bool> forward = {n == 1 || meets(curves[0]->EndPoint(), curves[1]->StartPoint()) ||
                               meets(curves[0]->EndPoint(), curves[1]->EndPoint())};
  for (std::size_t k = 1; k < n; ++k) {
    const gp_Pnt exit = exitOf(*curves[k - 1], forward[k - 1]);
    if (!meets(curves[k]->StartPoint(), exit) && !meets(curves[k]->EndPoint(), exit))
      throw Error(ErrorCode::InvalidModel, "a profile's curves do not join end to end");
    forward.push_back(meets(curves[k]->StartPoint(), exit));
  }
  if (!runsRound(curves, forward)) throw Error(ErrorCode::InvalidModel, "a profile's curves do not close");
  return forward;
}

/// The loop running the curves in the given directions. `shared[k]`, where not null, is
/// taken as its entry vertex of curve k (where another loop touches this one).
Loop loopOf(const std::vector<Handle(Geom_BSplineCurve)>& curves, const std::vector<bool>& forward,
            const std::vector<TopoDS_Vertex>& shared = {}) {
  const std::size_t n = curves.size();
  Loop loop;
  std::vector<gp_Pnt> entryPoints;
  for (std::size_t k = 0; k < n; ++k) entryPoints.push_back(entryOf(*curves[k], forward[k]));

  BRep_Builder builder;
  for (std::size_t k = 0; k < n; ++k) {
    TopoDS_Vertex vertex = k < shared.size() ? shared[k] : TopoDS_Vertex();
    if (vertex.IsNull()) builder.MakeVertex(vertex, entryPoints[k], kSewingTolerance);
    loop.entries.push_back(vertex);
  }
  builder.MakeWire(loop.wire);
  for (std::size_t k = 0; k < n; ++k) {
    const TopoDS_Vertex& entry = loop.entries[k];
    const TopoDS_Vertex& leave = loop.entries[(k + 1) % n];
    TopoDS_Edge edge;
    builder.MakeEdge(edge, curves[k], kTolerance);
    builder.Add(edge, (forward[k] ? entry : leave).Oriented(TopAbs_FORWARD));
    builder.Add(edge, (forward[k] ? leave : entry).Oriented(TopAbs_REVERSED));
    builder.Range(edge, curves[k]->FirstParameter(), curves[k]->LastParameter());
    loop.edges.push_back(edge);
    builder.Add(loop.wire, forward[k] ? edge : TopoDS::Edge(edge.Reversed()));
  }
  loop.wire.Closed(true);
  return loop;
}

/// The straight edge from a vertex of one loop to the matching vertex of the other; a
/// degenerate edge (no curve in space, only in the faces' parameters) where the loops share
/// the vertex.
TopoDS_Edge sideEdge(const TopoDS_Vertex& from, const TopoDS_Vertex& to) {
  BRep_Builder builder;
  TopoDS_Edge edge;
  if (from.IsSame(to)) {
    builder.MakeEdge(edge);
    builder.Degenerated(edge, true);
  } else {
    builder.MakeEdge(edge, straightLine(BRep_Tool::Pnt(from), BRep_Tool::Pnt(to)), kTolerance);
  }
  builder.Add(edge, from.Oriented(TopAbs_FORWARD));
  builder.Add(edge, to.Oriented(TopAbs_REVERSED));
  builder.Range(edge, 0.0, 1.0);
  return edge;
}

/// The line u = const of a face's parameter plane, running with v.
Handle(Geom2d_Line) alongV(double u) { return new Geom2d_Line(gp_Pnt2d(u, 0.0), gp_Dir2d(0.0, 1.0)); }

/// The line v = const, running with u.
Handle(Geom2d_Line) alongU(double v) { return new Geom2d_Line(gp_Pnt2d(0.0, v), gp_Dir2d(1.0, 0.0)); }

/// The ruled surface S(u, v) between two curves over the same range (v = 0 on the first) as
/// a face on the edges of those curves and the side edges at the curves' start and end (one
/// seam edge for closed curves). The edges carry their exact lines in (u, v), so, built
/// directly, nothing needs checking (OCCT's ruled skin spent most of its time on that).
TopoDS_Face ruledSideFace(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & last,
                          const TopoDS_Edge& onFirst, const TopoDS_Edge& onLast, const TopoDS_Edge& sideAtStart,
                          const TopoDS_Edge& sideAtEnd) {
  const double u0 = first->FirstParameter(), u1 = first->LastParameter();
  if (std::abs(u0 - last->FirstParameter()) > 1e-12 || std::abs(u1 - last->LastParameter()) > 1e-12)
    throw Error(ErrorCode::InvalidModel, "the two profiles' curves span different parameter ranges");
  const std::vector<double> sites = {0.0, 1.0};
  BRep_Builder builder;
  TopoDS_Face face;
  builder.MakeFace(face, skinCurves({first, last}, sites, skinningSpace(sites, 1, false)), kTolerance);
  builder.UpdateEdge(onFirst, alongU(0.0), face, kTolerance);
  builder.UpdateEdge(onLast, alongU(1.0), face, kTolerance);
  if (sideAtStart.IsSame(sideAtEnd)) {
    builder.UpdateEdge(sideAtEnd, alongV(u1), alongV(u0), face, kTolerance);
  } else {
    builder.UpdateEdge(sideAtStart, alongV(u0), face, kTolerance);
    builder.UpdateEdge(sideAtEnd, alongV(u1), face, kTolerance);
  }
  // Anticlockwise in (u, v): along the first curve, up the end side, back along the last
  // curve, down the start side.
  TopoDS_Wire boundary;
  builder.MakeWire(boundary);
  builder.Add(boundary, onFirst);
  builder.Add(boundary, sideAtEnd);
  builder.Add(boundary, onLast.Reversed());
  builder.Add(boundary, sideAtStart.Reversed());
  boundary.Closed(true);
  builder.Add(face, boundary);
  return face;
}

}  // namespace

RuledLoft ruledLoft(const std::vector<Handle(Geom_BSplineCurve)>& first,
                    const std::vector<Handle(Geom_BSplineCurve)>& last) {
  if (first.empty() || first.size() != last.size())
    throw Error(ErrorCode::InvalidModel, "the two profiles have different numbers of curves");
  // Both loops run their curves the same way; a curve shrunk to a point runs either way,
  // so one loop may take the other's directions.
  std::vector<bool> forward = directionsOf(first);
  if (const std::vector<bool> other = directionsOf(last); other != forward) {
    if (!runsRound(last, forward)) {
      if (!runsRound(first, other)) throw Error(ErrorCode::InvalidModel, "the two profiles run differently");
      forward = other;
    }
  }
  const Loop a = loopOf(first, forward);
  const std::size_t n = first.size();
  // Where the profiles touch (a segment tapering to a point, or of no length), the second
  // loop takes the first one's vertex and the side edge there degenerates.
  std::vector<TopoDS_Vertex> touching(n);
  for (std::size_t k = 0; k < n; ++k)
    if (meets(BRep_Tool::Pnt(a.entries[k]), entryOf(*last[k], forward[k]))) touching[k] = a.entries[k];
  const Loop b = loopOf(last, forward, touching);
  std::vector<TopoDS_Edge> sides;
  for (std::size_t k = 0; k < n; ++k) sides.push_back(sideEdge(a.entries[k], b.entries[k]));

  BRep_Builder builder;
  RuledLoft loft;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (std::size_t k = 0; k < n; ++k) {
    const TopoDS_Edge& entrySide = sides[k];
    const TopoDS_Edge& leaveSide = sides[(k + 1) % n];
    const TopoDS_Face face = ruledSideFace(first[k], last[k], a.edges[k], b.edges[k],
                                           forward[k] ? entrySide : leaveSide, forward[k] ? leaveSide : entrySide);
    // Where the loop runs against the curve, the face turns too, so that each side edge is
    // run once each way by the two faces that share it.
    loft.sides.push_back(forward[k] ? face : TopoDS::Face(face.Reversed()));
    builder.Add(shell, loft.sides.back());
  }
  // The lines in the faces' parameters run over the edges' ranges (a degenerate side edge
  // has no other curve to take its range from).
  for (const TopoDS_Edge& side : sides) builder.Range(side, 0.0, 1.0);
  for (std::size_t k = 0; k < n; ++k) {
    builder.Range(a.edges[k], first[k]->FirstParameter(), first[k]->LastParameter());
    builder.Range(b.edges[k], last[k]->FirstParameter(), last[k]->LastParameter());
  }
  TopTools_IndexedDataMapOfShapeListOfShape facesOfEdges;
  TopExp::MapShapesAndAncestors(shell, TopAbs_EDGE, TopAbs_FACE, facesOfEdges);
  // The caps lie on the profiles' own edges, turned against the sides.
  loft.firstCap = facingTheSides(planarFaceOn(a.wire), facesOfEdges);
  loft.lastCap = facingTheSides(planarFaceOn(b.wire), facesOfEdges);
  builder.Add(shell, loft.firstCap);
  builder.Add(shell, loft.lastCap);
  shell.Closed(true);
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  loft.solid = outwards(solid);
  return loft;
}

}  // namespace airshape::geometry
