#include "airshape/model/cst_airfoil.h"

#include <cmath>
#include <utility>

#include "airshape/error.h"
#include "airshape/model/placement.h"

namespace airshape::model {

namespace {

/// A CST number that must be finite and not negative: an exponent of the class function
/// x^N1 (1 − x)^N2 (negative, it is infinite at an end) or the trailing-edge thickness.
double notNegative(double value, const std::string& xpath) {
  if (!(finite(value, xpath) >= 0.0)) throw Error(ErrorCode::InvalidModel, "must not be negative", {}, xpath);
  return value;
}

}  // namespace

CstSide::CstSide(double n1, double n2, std::vector<double> coefficients, double thickness, double sign)
    : n1_(n1), n2_(n2), b_(std::move(coefficients)), thickness_(thickness), sign_(sign) {}

gp_Pnt CstSide::operator()(double xsi) const {
  const double x = chordwise(xsi);
  const double n = static_cast<double>(b_.size()) - 1.0;
  double shape = 0.0;
  for (std::size_t i = 0; i < b_.size(); ++i) {
    const double k = static_cast<double>(i);
    shape += b_[i] * std::tgamma(n + 1.0) / (std::tgamma(k + 1.0) * std::tgamma(n - k + 1.0)) * std::pow(x, k) *
             std::pow(1.0 - x, n - k);
  }
  const double z = std::pow(x, n1_) * std::pow(1.0 - x, n2_) * shape + x * thickness_ / 2.0;
  return gp_Pnt(x, 0.0, sign_ * z);
}

double CstSide::chordwise(double xsi) const {
  if (n1_ >= 1.0 && n2_ >= 1.0) return xsi;
  if (n1_ < 1.0 && n2_ >= 1.0) return xsi * xsi;
  if (n1_ >= 1.0) return 2.0 * xsi - xsi * xsi;
  return 3.0 * xsi * xsi - 2.0 * xsi * xsi * xsi;
}

CstAirfoil CstAirfoil::read(const schema::Cst2DType& cst, const std::string& xpath) {
  const double thickness = notNegative(cst.trailingEdgeThickness.value_or(0.0), xpath + "/trailingEdgeThickness");
  CstAirfoil airfoil{CstSide(notNegative(cst.upperN1, xpath + "/upperN1"), notNegative(cst.upperN2, xpath + "/upperN2"),
                             parseVector(cst.upperB, xpath + "/upperB"), thickness, 1.0),
                     CstSide(notNegative(cst.lowerN1, xpath + "/lowerN1"), notNegative(cst.lowerN2, xpath + "/lowerN2"),
                             parseVector(cst.lowerB, xpath + "/lowerB"), thickness, -1.0),
                     thickness > 0.0};
  // An exponent of 0 leaves the side's end at its first or last coefficient, off the chord.
  constexpr double kApart = 1e-9;  // of the chord
  if (airfoil.upper(0.0).Distance(airfoil.lower(0.0)) > kApart)
    throw Error(ErrorCode::InvalidModel, "the upper and lower sides do not meet at the leading edge (an N1 of 0?)", {},
                xpath);
  if (!airfoil.bluntTrailingEdge && airfoil.upper(1.0).Distance(airfoil.lower(1.0)) > kApart)
    throw Error(ErrorCode::InvalidModel,
                "the upper and lower sides do not meet at the sharp trailing edge (an N2 of 0? a gap there needs a "
                "trailingEdgeThickness)",
                {}, xpath);
  return airfoil;
}

}  // namespace airshape::model
