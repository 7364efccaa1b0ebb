#include "airshape/geometry/parameter_region.h"

#include <algorithm>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

namespace airshape::geometry {

namespace {

/// A curve of the parameter plane (u, v) as the curve (u, v, 0): the same poles, weights and
/// knots.
Handle(Geom_BSplineCurve) lifted(const Handle(Geom2d_BSplineCurve) & curve) {
  TColgp_Array1OfPnt poles(1, curve->NbPoles());
  for (int i = 1; i <= curve->NbPoles(); ++i) poles.SetValue(i, gp_Pnt(curve->Pole(i).X(), curve->Pole(i).Y(), 0.0));
  TColStd_Array1OfReal knots(1, curve->NbKnots());
  TColStd_Array1OfInteger multiplicities(1, curve->NbKnots());
  curve->Knots(knots);
  curve->Multiplicities(multiplicities);
  if (!curve->IsRational()) return new Geom_BSplineCurve(poles, knots, multiplicities, curve->Degree());
  TColStd_Array1OfReal weights(1, curve->NbPoles());
  curve->Weights(weights);
  return new Geom_BSplineCurve(poles, weights, knots, multiplicities, curve->Degree());
}

/// The other way: the curve (u, v, 0) as the curve (u, v).
Handle(Geom2d_BSplineCurve) flattened(const Handle(Geom_BSplineCurve) & curve) {
  TColgp_Array1OfPnt2d poles(1, curve->NbPoles());
  for (int i = 1; i <= curve->NbPoles(); ++i) poles.SetValue(i, gp_Pnt2d(curve->Pole(i).X(), curve->Pole(i).Y()));
  TColStd_Array1OfReal knots(1, curve->NbKnots());
  TColStd_Array1OfInteger multiplicities(1, curve->NbKnots());
  curve->Knots(knots);
  curve->Multiplicities(multiplicities);
  if (!curve->IsRational()) return new Geom2d_BSplineCurve(poles, knots, multiplicities, curve->Degree());
  TColStd_Array1OfReal weights(1, curve->NbPoles());
  curve->Weights(weights);
  return new Geom2d_BSplineCurve(poles, weights, knots, multiplicities, curve->Degree());
}

}  // namespace

std::optional<PlaneRegion> parameterRegionOf(const TopoDS_Face& face) {
  int wires = 0;
  for (TopExp_Explorer wire(face, TopAbs_WIRE); wire.More(); wire.Next()) ++wires;
  if (wires != 1) return std::nullopt;
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (BRepTools_WireExplorer edge(BRepTools::OuterWire(face), face); edge.More(); edge.Next()) {
    double first = 0.0, last = 0.0;
    const Handle(Geom2d_Curve) onSurface = BRep_Tool::CurveOnSurface(edge.Current(), face, first, last);
    if (onSurface.IsNull()) return std::nullopt;
    Handle(Geom2d_BSplineCurve) spline =
        Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(onSurface, first, last));
    if (edge.Current().Orientation() == TopAbs_REVERSED) spline->Reverse();
    curves.push_back(lifted(spline));
  }
  return regionInside(kParameterPlane, curves);
}

std::optional<TopoDS_Face> faceOnSurface(const Handle(Geom_Surface) & surface, const TopoDS_Face& parameterFace,
                                         const TopoDS_Face& like) {
  std::vector<Handle(Geom2d_BSplineCurve)> curves;
  for (BRepTools_WireExplorer edge(BRepTools::OuterWire(parameterFace), parameterFace); edge.More(); edge.Next()) {
    double first = 0.0, last = 0.0;
    const Handle(Geom_BSplineCurve) curve =
        Handle(Geom_BSplineCurve)::DownCast(BRep_Tool::Curve(edge.Current(), first, last));
    if (curve.IsNull()) return std::nullopt;
    Handle(Geom_BSplineCurve) piece = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
    if (first > piece->FirstParameter() || last < piece->LastParameter()) piece->Segment(first, last);
    Handle(Geom2d_BSplineCurve) image = flattened(piece);
    if (edge.Current().Orientation() == TopAbs_REVERSED) image->Reverse();
    curves.push_back(image);
  }
  // One vertex on the surface where each curve ends and the next begins.
  BRep_Builder builder;
  std::vector<TopoDS_Vertex> vertices;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const gp_Pnt2d end = curves[i]->EndPoint(), next = curves[(i + 1) % curves.size()]->StartPoint();
    const gp_Pnt at = surface->Value(end.X(), end.Y()), nextAt = surface->Value(next.X(), next.Y());
    TopoDS_Vertex vertex;
    builder.MakeVertex(vertex, gp_Pnt(0.5 * (at.XYZ() + nextAt.XYZ())), std::max(1e-7, at.Distance(nextAt)));
    vertices.push_back(vertex);
  }
  BRepBuilderAPI_MakeWire wire;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const TopoDS_Vertex& from = vertices[(i + curves.size() - 1) % curves.size()];
    BRepBuilderAPI_MakeEdge edge(curves[i], surface, from, vertices[i], curves[i]->FirstParameter(),
                                 curves[i]->LastParameter());
    if (!edge.IsDone()) return std::nullopt;
    wire.Add(edge.Edge());
    if (!wire.IsDone()) return std::nullopt;
  }
  BRepBuilderAPI_MakeFace face(surface, wire.Wire(), false);  // counterclockwise in (u, v): its inside
  if (!face.IsDone()) return std::nullopt;
  TopoDS_Face made = face.Face();
  BRepLib::BuildCurves3d(made);
  if (like.Orientation() == TopAbs_REVERSED) made.Reverse();
  return made;
}

}  // namespace airshape::geometry
