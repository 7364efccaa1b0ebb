#include "airshape/geometry/brep_building.h"

#include <cmath>
#include <optional>
#include <type_traits>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/skinning.h"

namespace airshape::geometry {

namespace {

/// A solid enclosing less than this fraction of its box diagonal cubed encloses nothing.
constexpr double kEmptyVolume = 1e-12;
/// A profile thinner on average (its area over its box diagonal) than this many sewing
/// tolerances encloses nothing: its cap would be a face whose edges touch.
constexpr double kThinnest = 10.0;

/// Whether `area`, bounded by these curves, is none (see enclosesNoArea).
bool isNoArea(double area, const std::vector<Handle(Geom_BSplineCurve)>& boundary) {
  Bnd_Box poles;
  for (const auto& curve : boundary)
    for (int i = 1; i <= curve->NbPoles(); ++i) poles.Add(curve->Pole(i));
  return std::abs(area) <= kThinnest * kJoinTolerance * (poles.IsVoid() ? 0.0 : std::sqrt(poles.SquareExtent()));
}

/// The B-spline curves of a wire's edges; nothing when an edge is not a B-spline.
std::optional<std::vector<Handle(Geom_BSplineCurve)>> splinesOf(const TopoDS_Wire& wire) {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (TopExp_Explorer edges(wire, TopAbs_EDGE); edges.More(); edges.Next()) {
    double first, last;
    const auto curve =
        Handle(Geom_BSplineCurve)::DownCast(BRep_Tool::Curve(TopoDS::Edge(edges.Current()), first, last));
    if (curve.IsNull()) return std::nullopt;
    curves.push_back(curve);
  }
  return curves;
}

/// The plane through every pole of the curves (their least-squares plane) when they all lie
/// on it within kBrepTolerance; nothing otherwise.
std::optional<gp_Pln> planeOfPoles(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  std::vector<gp_Pnt> poles;
  for (const auto& curve : curves)
    for (int i = 1; i <= curve->NbPoles(); ++i) poles.push_back(curve->Pole(i));
  return planeThroughPoints(poles, kBrepTolerance);
}

}  // namespace

std::optional<gp_Pln> planeThroughPoints(const std::vector<gp_Pnt>& points, double flatness) {
  if (points.size() < 3) return std::nullopt;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const gp_Pnt& p : points) centre += Eigen::Vector3d(p.X(), p.Y(), p.Z());
  centre /= static_cast<double>(points.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const gp_Pnt& p : points) {
    const Eigen::Vector3d offset = Eigen::Vector3d(p.X(), p.Y(), p.Z()) - centre;
    spread += offset * offset.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(spread);
  if (axes.info() != Eigen::Success || !(axes.eigenvalues()(1) > 0.0)) return std::nullopt;  // a line or a point
  const Eigen::Vector3d normal = axes.eigenvectors().col(0);  // the direction of least spread
  for (const gp_Pnt& p : points)
    if (std::abs((Eigen::Vector3d(p.X(), p.Y(), p.Z()) - centre).dot(normal)) > flatness) return std::nullopt;
  return gp_Pln(gp_Pnt(centre.x(), centre.y(), centre.z()), gp_Dir(normal.x(), normal.y(), normal.z()));
}

static_assert(std::is_same_v<Affine3, Eigen::Affine3d>, "geometry/affine.h names Eigen's Affine3d");

Handle(Geom_BSplineCurve) transformed(const Handle(Geom_BSplineCurve) & curve, const Affine3& transform) {
  Handle(Geom_BSplineCurve) moved = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  for (int i = 1; i <= moved->NbPoles(); ++i) {
    const gp_Pnt pole = moved->Pole(i);
    const Eigen::Vector3d placed = transform * Eigen::Vector3d(pole.X(), pole.Y(), pole.Z());
    moved->SetPole(i, gp_Pnt(placed.x(), placed.y(), placed.z()));
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

TopoDS_Vertex vertexWithin(const gp_Pnt& point, double tolerance) {
  TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(point).Vertex();
  BRep_Builder().UpdateVertex(vertex, tolerance);
  return vertex;
}

Handle(Geom_BSplineSurface)
    ruledSurface(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & second) {
  const std::vector<double> sites = {0.0, 1.0};
  return skinCurves({first, second}, sites, skinningSpace(sites, 1, false));
}

TopoDS_Face ruledFace(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & second) {
  return BRepBuilderAPI_MakeFace(ruledSurface(first, second), kBrepTolerance).Face();
}

TopoDS_Face planarFace(const std::vector<Handle(Geom_BSplineCurve)>& boundary) {
  BRepBuilderAPI_MakeWire wire;
  for (const auto& curve : boundary) wire.Add(BRepBuilderAPI_MakeEdge(curve).Edge());
  if (!wire.IsDone()) throw Error(ErrorCode::InvalidModel, "the boundary curves do not join into a wire");
  return planarFace(wire.Wire());
}

TopoDS_Shape sewnSolid(const std::vector<TopoDS_Face>& faces, std::vector<TopoDS_Face>* sewnFaces, double tolerance,
                       Orienting orienting) {
  BRepBuilderAPI_Sewing sewing(tolerance);
  for (const TopoDS_Face& face : faces)
    if (!face.IsNull()) sewing.Add(face);
  sewing.Perform();
  TopExp_Explorer shells(sewing.SewedShape(), TopAbs_SHELL);
  if (!shells.More()) throw Error(ErrorCode::InvalidModel, "the faces do not close into a solid");
  TopoDS_Solid solid = BRepBuilderAPI_MakeSolid(TopoDS::Shell(shells.Current())).Solid();
  if (orienting == Orienting::ByVolume || !BRepLib::OrientClosedSolid(solid)) solid = outwards(solid);
  if (sewnFaces) {
    sewnFaces->clear();
    for (const TopoDS_Face& face : faces)
      sewnFaces->push_back(face.IsNull() || !sewing.IsModified(face) ? face : TopoDS::Face(sewing.Modified(face)));
  }
  return solid;
}

TopoDS_Face planarFace(const TopoDS_Wire& wire) {
  const auto curves = splinesOf(wire);
  if (!curves) return BRepBuilderAPI_MakeFace(wire, true).Face();
  std::optional<gp_Pln> plane = planeOfPoles(*curves);
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
  if (isNoArea(area, *curves) && !BRepCheck_Analyzer(face).IsValid()) throw noAreaError();
  return face;
}

bool enclosesNoArea(const TopoDS_Face& planarFace) {
  const auto curves = splinesOf(BRepTools::OuterWire(planarFace));
  return curves && isNoArea(areaOf(planarFace), *curves);
}

Error noAreaError(const std::string& cpacsPath) {
  return Error(ErrorCode::InvalidModel, "a profile encloses no area (scaled to no thickness?)", {}, cpacsPath);
}

TopoDS_Solid outwards(TopoDS_Solid solid, FlatSolid flat) {
  const double volume = roughSignedVolumeOf(solid);
  // The solid's scale: the box of its vertices costs next to nothing (the whole solid's box
  // is taken where the vertices all coincide).
  Bnd_Box box;
  for (TopExp_Explorer vertices(solid, TopAbs_VERTEX); vertices.More(); vertices.Next())
    box.Add(BRep_Tool::Pnt(TopoDS::Vertex(vertices.Current())));
  if (box.IsVoid() || box.SquareExtent() == 0.0) BRepBndLib::Add(solid, box);
  const double size = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
  if (std::abs(volume) <= kEmptyVolume * size * size * size) {
    if (flat == FlatSolid::Kept) return solid;
    throw Error(ErrorCode::InvalidModel, "the faces enclose no volume (a segment of zero length or thickness?)");
  }
  if (volume < 0) solid.Reverse();
  return solid;
}

}  // namespace airshape::geometry
