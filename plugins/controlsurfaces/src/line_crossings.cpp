#include "line_crossings.h"

#include <algorithm>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <Precision.hxx>
#include <TopoDS_Edge.hxx>

#include "airshape/error.h"

namespace airshape::controlsurfaces {

LineCrossings::LineCrossings(const TopoDS_Shape& shape) : shape_(shape) {}

LineCrossings::~LineCrossings() = default;

std::vector<LineCrossing> LineCrossings::of(const gp_Lin& line, double merge) {
  if (!intersector_) {
    intersector_ = std::make_unique<IntCurvesFace_ShapeIntersector>();
    intersector_->Load(shape_, 1e-7);
  }
  intersector_->Perform(line, -Precision::Infinite(), Precision::Infinite());
  std::vector<LineCrossing> crossings;
  for (int i = 1; intersector_->IsDone() && i <= intersector_->NbPnt(); ++i) {
    gp_Pnt p;
    gp_Vec du, dv;
    BRep_Tool::Surface(intersector_->Face(i))->D1(intersector_->UParameter(i), intersector_->VParameter(i), p, du, dv);
    crossings.push_back({intersector_->WParameter(i), intersector_->Pnt(i), du.Crossed(dv)});
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const LineCrossing& a, const LineCrossing& b) { return a.along < b.along; });
  crossings.erase(std::unique(crossings.begin(), crossings.end(),
                              [&](const LineCrossing& a, const LineCrossing& b) { return b.along - a.along < merge; }),
                  crossings.end());
  return crossings;
}

std::vector<LineCrossing> crossingsOf(const TopoDS_Shape& shape, const gp_Lin& line, double merge) {
  return LineCrossings(shape).of(line, merge);
}

gp_Pnt nearestToLine(const TopoDS_Shape& shape, const gp_Lin& line, double reach) {
  const TopoDS_Edge segment = BRepBuilderAPI_MakeEdge(line, -reach, reach).Edge();
  BRepExtrema_DistShapeShape distance(segment, shape);
  if (!distance.IsDone() || distance.NbSolution() == 0)
    throw Error(ErrorCode::InvalidModel, "no skin to place the point on");
  gp_Pnt nearest = distance.PointOnShape2(1);
  for (int k = 2; k <= distance.NbSolution(); ++k)
    if (distance.PointOnShape2(k).Distance(line.Location()) < nearest.Distance(line.Location()))
      nearest = distance.PointOnShape2(k);
  return nearest;
}

}  // namespace airshape::controlsurfaces
