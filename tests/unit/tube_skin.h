#pragma once

#include <cmath>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomConvert.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax3.hxx>

namespace airshape::test {

/// The skin of a tube about the x axis from x = 0 to 4, one untrimmed B-spline face (an exact
/// rational cylinder) whose seam lies at +z; `turn` (radians) keeps only that much of it round
/// from +z towards −y.
inline TopoDS_Face tubeSkin(double radius, double turn = 2 * M_PI) {
  const Handle(Geom_CylindricalSurface) cylinder =
      new Geom_CylindricalSurface(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0), gp_Dir(0, 0, 1)), radius);
  const Handle(Geom_RectangularTrimmedSurface) piece =
      new Geom_RectangularTrimmedSurface(cylinder, 0.0, turn, 0.0, 4.0);
  return BRepBuilderAPI_MakeFace(GeomConvert::SurfaceToBSplineSurface(piece), 1e-9).Face();
}

}  // namespace airshape::test
