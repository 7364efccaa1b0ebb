#pragma once

#include <vector>

#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>

namespace airshape::geometry {

/// Finds the nearest point of a surface to given points: the nearest of a grid of surface
/// samples, refined by Newton's method. Built once per surface, then cheap per point.
class SurfaceProjector {
 public:
  explicit SurfaceProjector(Handle(Geom_BSplineSurface) surface, int gridSize = 120);

  /// The distance from `point` to the surface.
  double distance(const gp_Pnt& point) const;

 private:
  Handle(Geom_BSplineSurface) surface_;
  std::vector<gp_Pnt> grid_;
  std::vector<double> u_, v_;
  double u1_ = 0, u2_ = 0, v1_ = 0, v2_ = 0;
};

}  // namespace airshape::geometry
