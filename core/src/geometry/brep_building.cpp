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
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
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
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/skinning.h"

namespace airshape::geometry {

namespace {

constexpr double kTolerance = 1e-7;
constexpr double kSewingTolerance = 1e-6;
/// A solid enclosing less than this fraction of its box diagonal cubed encloses nothing.
constexpr double kEmptyVolume = 1e-12;

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
  std::optional<gp_Pln> plane = planeOfPoles(curves);
  if (!plane) {
    BRepBuilderAPI_MakeFace face(wire, true);
    if (!face.IsDone()) throw Error(ErrorCode::InvalidModel, "a profile is not planar, so no planar cap closes it");
    return face.Face();
  }
  if (signedAreaEnclosed(wire, plane->Axis().Direction()) < 0.0)
    plane = gp_Pln(plane->Location(), plane->Axis().Direction().Reversed());
  BRepBuilderAPI_MakeFace face(*plane, wire, false);
  if (!face.IsDone()) throw Error(ErrorCode::InvalidModel, "a profile is not planar, so no planar cap closes it");
  return face.Face();
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
  Bnd_Box box;  // of the edges: the solid's scale, at a fraction of the cost of its faces' box
  for (TopExp_Explorer edges(solid, TopAbs_EDGE); edges.More(); edges.Next()) BRepBndLib::Add(edges.Current(), box);
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

RuledLoft ruledLoft(const TopoDS_Wire& first, const TopoDS_Wire& last) {
  BRepOffsetAPI_ThruSections sides(false, true, kSewingTolerance);
  sides.CheckCompatibility(false);
  sides.AddWire(first);
  sides.AddWire(last);
  sides.Build();
  if (!sides.IsDone()) throw Error(ErrorCode::InvalidModel, "no ruled skin joins the two profiles");
  TopTools_IndexedDataMapOfShapeListOfShape facesOfEdges;
  TopExp::MapShapesAndAncestors(sides.Shape(), TopAbs_EDGE, TopAbs_FACE, facesOfEdges);
  RuledLoft loft;
  // The ruled skin keeps the wires' own edges along its ends: the caps share them.
  loft.firstCap = facingTheSides(planarFaceOn(first), facesOfEdges);
  loft.lastCap = facingTheSides(planarFaceOn(last), facesOfEdges);
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (TopExp_Explorer faces(sides.Shape(), TopAbs_FACE); faces.More(); faces.Next())
    builder.Add(shell, faces.Current());
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
