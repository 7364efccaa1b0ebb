#pragma once

#include <cstddef>
#include <vector>

#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_XYZ.hxx>

namespace airshape::geometry {

/// Finds the nearest point of a surface to given points: the nearest of a grid of surface
/// samples, refined by Newton's method. Built once per surface, then cheap per point: the grid
/// is searched block by block, nearest block first, up to the first block farther away than
/// the points found.
class SurfaceProjector {
 public:
  explicit SurfaceProjector(Handle(Geom_BSplineSurface) surface, int gridSize = 120);

  /// The distance from `point` to the surface.
  double distance(const gp_Pnt& point) const;

 private:
  /// A square of grid points (rows i0..i1-1, columns j0..j1-1) and the box round them.
  struct Block {
    std::size_t i0, i1, j0, j1;
    gp_XYZ low, high;
  };

  /// The indices of the `count` grid points nearest to `point`, nearest first.
  std::vector<std::size_t> nearestGridPoints(const gp_Pnt& point, std::size_t count) const;

  Handle(Geom_BSplineSurface) surface_;
  std::vector<gp_Pnt> grid_;
  std::vector<double> u_, v_;
  std::vector<Block> blocks_;
  double u1_ = 0, u2_ = 0, v1_ = 0, v2_ = 0;
};

}  // namespace airshape::geometry
