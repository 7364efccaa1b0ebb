#include "line_crossings.h"

#include <algorithm>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepIntCurveSurface_Inter.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Edge.hxx>

#include "airshape/error.h"

namespace airshape::controlsurfaces {

std::vector<LineCrossing> crossingsOf(const TopoDS_Shape& shape, const gp_Lin& line, double merge) {
  std::vector<LineCrossing> crossings;
  BRepIntCurveSurface_Inter intersector;
  for (intersector.Init(shape, line, 1e-7); intersector.More(); intersector.Next()) {
    gp_Pnt p;
    gp_Vec du, dv;
    BRep_Tool::Surface(intersector.Face())->D1(intersector.U(), intersector.V(), p, du, dv);
    crossings.push_back({intersector.W(), intersector.Pnt(), du.Crossed(dv)});
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const LineCrossing& a, const LineCrossing& b) { return a.along < b.along; });
  crossings.erase(std::unique(crossings.begin(), crossings.end(),
                              [&](const LineCrossing& a, const LineCrossing& b) { return b.along - a.along < merge; }),
                  crossings.end());
  return crossings;
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
