#include "airshape/geometry/plane_face_within.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Plane.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

namespace {

/// An edge's course as a B-spline over its own parameter range.
Handle(Geom_BSplineCurve) courseOf(const TopoDS_Edge& edge) {
  double first = 0.0, last = 0.0;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
  if (curve.IsNull()) throw Error(ErrorCode::InvalidModel, "an edge of the bounding wire has no course in space");
  return GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, first, last));
}

/// The orthogonal projection of a B-spline onto a plane, in the plane's parameters: the same
/// knots and weights, each pole projected (projection is affine, so the curve projects exactly).
Handle(Geom2d_BSplineCurve) projected(const Handle(Geom_BSplineCurve) & course, const gp_Pln& plane) {
  const gp_Ax3& axes = plane.Position();
  TColgp_Array1OfPnt2d poles(1, course->NbPoles());
  for (int i = 1; i <= course->NbPoles(); ++i) {
    const gp_Vec offset(axes.Location(), course->Pole(i));
    poles(i) = gp_Pnt2d(offset.Dot(gp_Vec(axes.XDirection())), offset.Dot(gp_Vec(axes.YDirection())));
  }
  if (course->IsRational())
    return new Geom2d_BSplineCurve(poles, *course->Weights(), course->Knots(), course->Multiplicities(),
                                   course->Degree(), course->IsPeriodic());
  return new Geom2d_BSplineCurve(poles, course->Knots(), course->Multiplicities(), course->Degree(),
                                 course->IsPeriodic());
}

/// The farthest a B-spline strays from a plane: at most as far as its farthest pole.
double strayOf(const Handle(Geom_BSplineCurve) & course, const gp_Pln& plane) {
  double stray = 0.0;
  for (int i = 1; i <= course->NbPoles(); ++i) stray = std::max(stray, plane.Distance(course->Pole(i)));
  return stray;
}

/// Twice the signed area inside a closed chain of 2D curves, from points along them.
double twiceSignedArea(const std::vector<Handle(Geom2d_BSplineCurve)>& curves, const std::vector<bool>& reversed) {
  constexpr int kSamples = 32;
  std::vector<gp_Pnt2d> points;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const double first = curves[k]->FirstParameter(), last = curves[k]->LastParameter();
    for (int i = 0; i < kSamples; ++i) {
      const double share = static_cast<double>(i) / kSamples;
      points.push_back(curves[k]->Value(reversed[k] ? last - share * (last - first) : first + share * (last - first)));
    }
  }
  double twice = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const gp_Pnt2d &a = points[i], &b = points[(i + 1) % points.size()];
    twice += a.X() * b.Y() - b.X() * a.Y();
  }
  return twice;
}

}  // namespace

TopoDS_Face planeFaceWithin(const gp_Pln& plane, const TopoDS_Wire& given) {
  if (!BRep_Tool::IsClosed(given)) throw Error(ErrorCode::InvalidModel, "the bounding wire is open");
  const TopoDS_Wire wire = TopoDS::Wire(BRepBuilderAPI_Copy(given).Shape());
  std::vector<TopoDS_Edge> edges;
  std::vector<Handle(Geom2d_BSplineCurve)> curves;
  std::vector<bool> reversed;
  std::vector<double> strays;
  for (BRepTools_WireExplorer along(wire); along.More(); along.Next()) {
    const TopoDS_Edge& edge = along.Current();
    const Handle(Geom_BSplineCurve) course = courseOf(edge);
    edges.push_back(edge);
    curves.push_back(projected(course, plane));
    reversed.push_back(edge.Orientation() == TopAbs_REVERSED);
    strays.push_back(strayOf(course, plane));
  }
  const double area = twiceSignedArea(curves, reversed);
  if (edges.empty() || std::abs(area) <= 0.0) throw Error(ErrorCode::InvalidModel, "the bounding wire bounds nothing");
  BRep_Builder builder;
  TopoDS_Face face;
  builder.MakeFace(face, new Geom_Plane(plane), Precision::Confusion());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const double tolerance = std::max(Precision::Confusion(), 1.001 * strays[k]);
    builder.UpdateEdge(edges[k], curves[k], face, tolerance);
    TopoDS_Vertex first, last;
    TopExp::Vertices(edges[k], first, last);
    builder.UpdateVertex(first, tolerance);
    builder.UpdateVertex(last, tolerance);
  }
  // The outer wire runs anticlockwise about the plane's normal.
  builder.Add(face, area > 0.0 ? wire : TopoDS::Wire(wire.Reversed()));
  return face;
}

}  // namespace airshape::geometry
