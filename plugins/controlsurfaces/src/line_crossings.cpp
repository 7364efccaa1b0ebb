#include "line_crossings.h"

#include <algorithm>

#include <BRepIntCurveSurface_Inter.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>

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

}  // namespace airshape::controlsurfaces
