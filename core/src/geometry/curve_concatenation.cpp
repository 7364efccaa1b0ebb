#include "airshape/geometry/curve_concatenation.h"

#include <algorithm>
#include <cmath>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

Handle(Geom_BSplineCurve) concatenateCurves(std::vector<Handle(Geom_BSplineCurve)> pieces) {
  if (pieces.empty()) throw Error(ErrorCode::InvalidArgument, "no curves to concatenate");
  int degree = 1;
  for (auto& piece : pieces) {
    piece = Handle(Geom_BSplineCurve)::DownCast(piece->Copy());
    if (piece->IsPeriodic()) piece->SetNotPeriodic();
    degree = std::max(degree, piece->Degree());
  }
  for (auto& piece : pieces) piece->IncreaseDegree(degree);
  std::vector<gp_Pnt> poles;
  std::vector<double> knots;
  std::vector<int> multiplicities;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const Geom_BSplineCurve& piece = *pieces[p];
    if (p > 0) {
      if (std::abs(piece.FirstParameter() - knots.back()) > 1e-9)
        throw Error(ErrorCode::InvalidArgument,
                    "a curve piece does not start at the parameter where the last one ends");
      multiplicities.back() = degree;  // the join: C0
    }
    for (int i = p == 0 ? 1 : 2; i <= piece.NbPoles(); ++i) poles.push_back(piece.Pole(i));
    for (int i = p == 0 ? 1 : 2; i <= piece.NbKnots(); ++i) {
      knots.push_back(piece.Knot(i));
      multiplicities.push_back(piece.Multiplicity(i));
    }
  }
  multiplicities.back() = degree + 1;
  TColgp_Array1OfPnt occPoles(1, static_cast<int>(poles.size()));
  for (std::size_t i = 0; i < poles.size(); ++i) occPoles(static_cast<int>(i) + 1) = poles[i];
  TColStd_Array1OfReal occKnots(1, static_cast<int>(knots.size()));
  TColStd_Array1OfInteger occMultiplicities(1, static_cast<int>(knots.size()));
  for (std::size_t i = 0; i < knots.size(); ++i) {
    occKnots(static_cast<int>(i) + 1) = knots[i];
    occMultiplicities(static_cast<int>(i) + 1) = multiplicities[i];
  }
  return new Geom_BSplineCurve(occPoles, occKnots, occMultiplicities, degree);
}

}  // namespace airshape::geometry
