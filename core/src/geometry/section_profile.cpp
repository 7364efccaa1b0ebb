#include "airshape/geometry/section_profile.h"

#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include "airshape/geometry/curve_fit.h"

namespace airshape::geometry {

namespace {

/// The skin's edges that lie in the plane (checked at nine points each).
std::vector<Handle(Geom_BSplineCurve)> edgesInPlane(const TopoDS_Shape& skin, const gp_Pln& plane, double tolerance) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(skin, TopAbs_EDGE, edges);
  std::vector<Handle(Geom_BSplineCurve)> inPlane;
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
    const BRepAdaptor_Curve curve(edge);
    bool lies = true;
    for (int k = 0; k <= 8 && lies; ++k)
      lies = plane.Distance(curve.Value(curve.FirstParameter() +
                                        (curve.LastParameter() - curve.FirstParameter()) * k / 8.0)) <= tolerance;
    if (lies) inPlane.push_back(edgeCurve(edge));
  }
  return inPlane;
}

}  // namespace

std::optional<PlaneRegion> profileInPlane(const TopoDS_Shape& upperSkin, const TopoDS_Shape& lowerSkin,
                                          const gp_Pln& plane, double tolerance) {
  const std::vector<Handle(Geom_BSplineCurve)> upper = edgesInPlane(upperSkin, plane, tolerance);
  const std::vector<Handle(Geom_BSplineCurve)> lower = edgesInPlane(lowerSkin, plane, tolerance);
  if (upper.size() != 1 || lower.size() != 1 || upper.front().IsNull() || lower.front().IsNull()) return std::nullopt;
  // The upper edge, then the lower one run on from the upper's end (the end nearer its start).
  const Handle(Geom_BSplineCurve)& top = upper.front();
  Handle(Geom_BSplineCurve) bottom = Handle(Geom_BSplineCurve)::DownCast(lower.front()->Copy());
  if (bottom->EndPoint().Distance(top->EndPoint()) < bottom->StartPoint().Distance(top->EndPoint())) bottom->Reverse();
  std::vector<Handle(Geom_BSplineCurve)> loop{top};
  if (top->EndPoint().Distance(bottom->StartPoint()) > tolerance)
    loop.push_back(straightCurve(top->EndPoint(), bottom->StartPoint()));
  loop.push_back(bottom);
  if (bottom->EndPoint().Distance(top->StartPoint()) > tolerance)
    loop.push_back(straightCurve(bottom->EndPoint(), top->StartPoint()));
  return regionInside(plane, loop);
}

}  // namespace airshape::geometry
