#pragma once

#include <string>
#include <vector>

#include <gp_Pnt.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::model {

/// One side of a CST airfoil: z(x) = ±(x^N1 (1−x)^N2 · Σ B_i C(n,i) x^i (1−x)^(n−i) + x·t/2),
/// evaluated exactly at x(xsi), whose form follows N1 and N2 so that xsi spreads points
/// where the side bends most.
class CstSide {
 public:
  CstSide(double n1, double n2, std::vector<double> coefficients, double thickness, double sign);

  /// The side's point at parameter xsi (0 at the leading edge, 1 at the trailing edge).
  gp_Pnt operator()(double xsi) const;

 private:
  double chordwise(double xsi) const;

  double n1_, n2_;
  std::vector<double> b_;
  double thickness_;
  double sign_;
};

/// A `cst2D` profile (an airfoil, a cowl's or a curve profile) read and checked: both sides and whether its
/// trailing edge is blunt.
struct CstAirfoil {
  CstSide upper, lower;
  bool bluntTrailingEdge = false;

  /// Throws Error naming the node when an exponent or the trailing-edge thickness is
  /// negative (a side would be infinite at an end) or when the sides do not meet at the
  /// leading edge or at a sharp trailing edge (an exponent of 0).
  static CstAirfoil read(const schema::Cst2DType& cst, const std::string& xpath);
};

}  // namespace airshape::model
