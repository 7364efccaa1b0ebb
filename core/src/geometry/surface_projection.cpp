#include "airshape/geometry/surface_projection.h"

#include <algorithm>
#include <cmath>

#include <gp_Vec.hxx>

namespace airshape::geometry {

SurfaceProjector::SurfaceProjector(Handle(Geom_BSplineSurface) surface, int gridSize) : surface_(std::move(surface)) {
  surface_->Bounds(u1_, u2_, v1_, v2_);
  for (int i = 0; i <= gridSize; ++i) {
    u_.push_back(u1_ + (u2_ - u1_) * i / gridSize);
    v_.push_back(v1_ + (v2_ - v1_) * i / gridSize);
  }
  for (double u : u_)
    for (double v : v_) grid_.push_back(surface_->Value(u, v));
}

double SurfaceProjector::distance(const gp_Pnt& point) const {
  // Start at the nearest few grid points and keep the best refinement.
  std::vector<std::pair<double, std::size_t>> nearest;
  for (std::size_t i = 0; i < grid_.size(); ++i) nearest.emplace_back(grid_[i].SquareDistance(point), i);
  const std::size_t starts = std::min<std::size_t>(3, nearest.size());
  std::partial_sort(nearest.begin(), nearest.begin() + static_cast<long>(starts), nearest.end());
  double best = HUGE_VAL;
  for (std::size_t s = 0; s < starts; ++s) {
    double u = u_[nearest[s].second / v_.size()], v = v_[nearest[s].second % v_.size()];
    for (int iteration = 0; iteration < 40; ++iteration) {
      gp_Pnt p;
      gp_Vec du, dv, duu, dvv, duv;
      surface_->D2(u, v, p, du, dv, duu, dvv, duv);
      const gp_Vec r(point, p);
      const double gu = r.Dot(du), gv = r.Dot(dv);
      const double huu = du.Dot(du) + r.Dot(duu), hvv = dv.Dot(dv) + r.Dot(dvv), huv = du.Dot(dv) + r.Dot(duv);
      const double det = huu * hvv - huv * huv;
      if (!(std::abs(det) > 1e-300)) break;
      const double stepU = (hvv * gu - huv * gv) / det, stepV = (huu * gv - huv * gu) / det;
      u = std::clamp(u - stepU, u1_, u2_);
      v = std::clamp(v - stepV, v1_, v2_);
      if (std::abs(stepU) < 1e-14 && std::abs(stepV) < 1e-14) break;
    }
    best = std::min(best, surface_->Value(u, v).Distance(point));
  }
  return best;
}

}  // namespace airshape::geometry
