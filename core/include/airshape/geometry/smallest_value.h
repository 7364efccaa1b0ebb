#pragma once

#include <functional>

namespace airshape::geometry {

/// Where a function of one variable takes its smallest value in [low, high], to within
/// `tolerance`, by Brent's method: a parabola through the three best points where it steps
/// well, golden sections where it does not. The function is taken to fall and then rise once in
/// the interval (as golden sections take it); on a smooth minimum the parabolas reach it in a
/// few steps where golden sections alone would need some sixty to close in to 1e-12.
double argumentOfMinimum(const std::function<double(double)>& function, double low, double high, double tolerance);

}  // namespace airshape::geometry
