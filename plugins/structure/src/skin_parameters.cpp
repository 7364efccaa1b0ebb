#include "skin_parameters.h"

#include <algorithm>
#include <cmath>

#include <BSplCLib.hxx>
#include <TColStd_Array1OfReal.hxx>

namespace airshape::structure {

namespace {

/// Knots closer than this are one knot.
constexpr double kSameKnot = 1e-14;

/// A copy of each curve over [0, 1] at the highest degree among them.
std::vector<Handle(Geom_BSplineCurve)> onCommonDegreeAndRange(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  int degree = 1;
  for (const auto& curve : curves) degree = std::max(degree, curve->Degree());
  std::vector<Handle(Geom_BSplineCurve)> result;
  for (const auto& curve : curves) {
    Handle(Geom_BSplineCurve) copy = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
    copy->IncreaseDegree(degree);
    TColStd_Array1OfReal knots(1, copy->NbKnots());
    copy->Knots(knots);
    BSplCLib::Reparametrize(0.0, 1.0, knots);
    copy->SetKnots(knots);
    result.push_back(copy);
  }
  return result;
}

/// Gives every curve the union of all their knots, each at its highest multiplicity.
void giveCommonKnots(std::vector<Handle(Geom_BSplineCurve)>& curves) {
  std::vector<double> knots;
  for (const auto& curve : curves)
    for (int i = 1; i <= curve->NbKnots(); ++i) knots.push_back(curve->Knot(i));
  std::sort(knots.begin(), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end(), [](double a, double b) { return std::abs(a - b) < kSameKnot; }),
              knots.end());
  std::vector<int> multiplicities(knots.size(), 0);
  for (const auto& curve : curves)
    for (int i = 1; i <= curve->NbKnots(); ++i) {
      const auto at = std::lower_bound(knots.begin(), knots.end(), curve->Knot(i) - kSameKnot);
      int& multiplicity = multiplicities[static_cast<std::size_t>(at - knots.begin())];
      multiplicity = std::max(multiplicity, curve->Multiplicity(i));
    }
  for (auto& curve : curves)
    for (std::size_t k = 0; k < knots.size(); ++k) curve->InsertKnot(knots[k], multiplicities[k], kSameKnot, false);
}

}  // namespace

std::vector<double> skinParameters(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  std::vector<Handle(Geom_BSplineCurve)> compatible = onCommonDegreeAndRange(curves);
  giveCommonKnots(compatible);
  const int rows = compatible.front()->NbPoles();
  std::vector<double> average(curves.size(), 0.0), cumulative(curves.size(), 0.0);
  for (int pole = 1; pole <= rows; ++pole) {
    for (std::size_t k = 1; k < compatible.size(); ++k)
      cumulative[k] = cumulative[k - 1] + std::sqrt(compatible[k]->Pole(pole).Distance(compatible[k - 1]->Pole(pole)));
    // Poles that do not move along the span (a degenerate row) count as evenly spaced.
    for (std::size_t k = 1; k < cumulative.size(); ++k)
      average[k] +=
          (cumulative.back() > 0.0 ? cumulative[k] / cumulative.back() : double(k) / double(curves.size() - 1)) / rows;
  }
  return average;
}

}  // namespace airshape::structure
