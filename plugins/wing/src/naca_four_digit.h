#pragma once

#include <utility>

#include <gp_Pnt.hxx>

namespace airshape::wing {

/// A NACA four-digit airfoil: the standard thickness law about the standard camber line,
/// the thickness law's last coefficient chosen so that the trailing edge has the given
/// thickness (-0.1015 would give the classic 0.00252 of a NACA 0012; closed by default).
class NacaFourDigit {
 public:
  NacaFourDigit(double camber, double camberAt, double thickness, double trailingEdge);

  double thickness() const { return thickness_; }

  /// The point of the upper (sign 1) or lower (sign -1) side above chord station x.
  gp_Pnt side(double x, double sign) const;

  /// The chord station at side parameter xsi: x = (1 + e)·xsi²/(xsi + e) with e = 0.02 is
  /// quadratic at the leading edge, which takes away the √x of the thickness law so that
  /// the side is smooth in xsi, and close to xsi elsewhere. The reference library
  /// parametrises its NACA sides the same way, and xsi of a point query depends on it.
  static double chordwise(double xsi);

 private:
  double halfThickness(double x) const;
  std::pair<double, double> camberLine(double x) const;  ///< height and slope

  double camber_, camberAt_, thickness_, a4_;
};

}  // namespace airshape::wing
