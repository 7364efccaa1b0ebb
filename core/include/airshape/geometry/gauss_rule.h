#pragma once

#include <math.hxx>
#include <math_Vector.hxx>

namespace airshape::geometry {

/// Gauss–Legendre points and weights on [-1, 1] (indices from 1, as OCCT's vectors count).
struct GaussRule {
  math_Vector points, weights;
  explicit GaussRule(int count) : points(1, count), weights(1, count) {
    math::GaussPoints(count, points);
    math::GaussWeights(count, weights);
  }
};

}  // namespace airshape::geometry
