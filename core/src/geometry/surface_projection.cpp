#include "airshape/geometry/surface_projection.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <gp_Vec.hxx>

namespace airshape::geometry {

namespace {

/// Grid points per block side: a block's box bounds its points' distances from below.
constexpr std::size_t kBlockSide = 8;

/// The squared distance from a point to an axis-aligned box (zero inside it).
double squareDistanceToBox(const gp_Pnt& point, const gp_XYZ& low, const gp_XYZ& high) {
  double sum = 0.0;
  for (int axis = 1; axis <= 3; ++axis) {
    const double x = point.Coord(axis);
    const double gap = x < low.Coord(axis) ? low.Coord(axis) - x : (x > high.Coord(axis) ? x - high.Coord(axis) : 0.0);
    sum += gap * gap;
  }
  return sum;
}

}  // namespace

SurfaceProjector::SurfaceProjector(Handle(Geom_BSplineSurface) surface, int gridSize) : surface_(std::move(surface)) {
  surface_->Bounds(u1_, u2_, v1_, v2_);
  for (int i = 0; i <= gridSize; ++i) {
    u_.push_back(u1_ + (u2_ - u1_) * i / gridSize);
    v_.push_back(v1_ + (v2_ - v1_) * i / gridSize);
  }
  for (double u : u_)
    for (double v : v_) grid_.push_back(surface_->Value(u, v));
  for (std::size_t i0 = 0; i0 < u_.size(); i0 += kBlockSide)
    for (std::size_t j0 = 0; j0 < v_.size(); j0 += kBlockSide) {
      Block block{i0, std::min(i0 + kBlockSide, u_.size()), j0, std::min(j0 + kBlockSide, v_.size()), {}, {}};
      block.low = block.high = grid_[i0 * v_.size() + j0].XYZ();
      for (std::size_t i = block.i0; i < block.i1; ++i)
        for (std::size_t j = block.j0; j < block.j1; ++j) {
          const gp_XYZ& p = grid_[i * v_.size() + j].XYZ();
          block.low.SetCoord(std::min(block.low.X(), p.X()), std::min(block.low.Y(), p.Y()),
                             std::min(block.low.Z(), p.Z()));
          block.high.SetCoord(std::max(block.high.X(), p.X()), std::max(block.high.Y(), p.Y()),
                              std::max(block.high.Z(), p.Z()));
        }
      blocks_.push_back(block);
    }
}

std::vector<std::size_t> SurfaceProjector::nearestGridPoints(const gp_Pnt& point, std::size_t count) const {
  // The blocks nearest first; a block whose box lies farther than the count-th nearest point
  // found so far holds none nearer. Points compare by (squared distance, index): the same
  // points, in the same order, as sorting the whole grid.
  std::vector<std::pair<double, std::size_t>> order;
  order.reserve(blocks_.size());
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    order.emplace_back(squareDistanceToBox(point, blocks_[b].low, blocks_[b].high), b);
  std::sort(order.begin(), order.end());
  std::vector<std::pair<double, std::size_t>> nearest;  // ascending, at most `count`
  for (const auto& [bound, b] : order) {
    if (nearest.size() == count && bound > nearest.back().first) break;
    const Block& block = blocks_[b];
    for (std::size_t i = block.i0; i < block.i1; ++i)
      for (std::size_t j = block.j0; j < block.j1; ++j) {
        const std::size_t index = i * v_.size() + j;
        const std::pair<double, std::size_t> candidate(grid_[index].SquareDistance(point), index);
        if (nearest.size() == count && !(candidate < nearest.back())) continue;
        nearest.insert(std::upper_bound(nearest.begin(), nearest.end(), candidate), candidate);
        if (nearest.size() > count) nearest.pop_back();
      }
  }
  std::vector<std::size_t> indices;
  for (const auto& entry : nearest) indices.push_back(entry.second);
  return indices;
}

double SurfaceProjector::distance(const gp_Pnt& point) const {
  // Start at the nearest few grid points and keep the best refinement.
  double best = HUGE_VAL;
  for (const std::size_t start : nearestGridPoints(point, 3)) {
    double u = u_[start / v_.size()], v = v_[start % v_.size()];
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
