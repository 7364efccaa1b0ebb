#pragma once

#include <functional>

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

namespace airshape::test {

/// A cubic B-spline sheet over [0, 10] × [0, 1] of 40 × 4 uniform spans (u from 0 to 40, v from
/// 0 to 4), its 43 × 7 poles evenly spread in x and y at the height `z(x, y)`.
inline Handle(Geom_BSplineSurface) sheetOfManySpans(const std::function<double(double x, double y)>& z) {
  constexpr int kUSpans = 40, kVSpans = 4, kDegree = 3;
  constexpr int kUPoles = kUSpans + kDegree, kVPoles = kVSpans + kDegree;
  TColgp_Array2OfPnt poles(1, kUPoles, 1, kVPoles);
  for (int i = 1; i <= kUPoles; ++i)
    for (int j = 1; j <= kVPoles; ++j) {
      const double x = 10.0 * (i - 1) / (kUPoles - 1), y = (j - 1) / (kVPoles - 1.0);
      poles(i, j) = gp_Pnt(x, y, z(x, y));
    }
  TColStd_Array1OfReal uKnots(1, kUSpans + 1), vKnots(1, kVSpans + 1);
  TColStd_Array1OfInteger uMultiplicities(1, kUSpans + 1), vMultiplicities(1, kVSpans + 1);
  for (int i = 1; i <= kUSpans + 1; ++i)
    uKnots(i) = i - 1, uMultiplicities(i) = (i == 1 || i == kUSpans + 1) ? kDegree + 1 : 1;
  for (int i = 1; i <= kVSpans + 1; ++i)
    vKnots(i) = i - 1, vMultiplicities(i) = (i == 1 || i == kVSpans + 1) ? kDegree + 1 : 1;
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMultiplicities, vMultiplicities, kDegree, kDegree);
}

}  // namespace airshape::test
