#include "airshape/geometry/compatibility.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "airshape/error.h"

namespace airshape::geometry {

namespace {

constexpr double kKnotTolerance = 1e-10;

/// Highest multiplicity of each knot value over several knot vectors (values merged
/// within kKnotTolerance).
class KnotUnion {
 public:
  void add(double knot, int multiplicity) {
    for (auto& [value, count] : knots_) {
      if (std::abs(value - knot) <= kKnotTolerance) {
        count = std::max(count, multiplicity);
        return;
      }
    }
    knots_.emplace_back(knot, multiplicity);
  }
  const std::vector<std::pair<double, int>>& knots() const { return knots_; }

 private:
  std::vector<std::pair<double, int>> knots_;
};

int multiplicityAt(const TColStd_Array1OfReal& knots, const TColStd_Array1OfInteger& multiplicities, double value) {
  for (int i = knots.Lower(); i <= knots.Upper(); ++i)
    if (std::abs(knots(i) - value) <= kKnotTolerance) return multiplicities(i);
  return 0;
}

void requireSameRange(double first, double last, double otherFirst, double otherLast) {
  if (std::abs(first - otherFirst) > 1e-9 || std::abs(last - otherLast) > 1e-9)
    throw Error(ErrorCode::InvalidArgument, "curves to be made compatible must share their parameter range");
}

/// Inserts into one direction of a surface every knot of `all` it lacks (or has too few
/// times), in one call: one pass over the poles rather than one per knot.
void insertMissing(Geom_BSplineSurface& surface, const KnotUnion& all, bool uDirection) {
  std::vector<std::pair<double, int>> missing;
  for (const auto& [value, multiplicity] : all.knots()) {
    const int present = uDirection ? multiplicityAt(surface.UKnots(), surface.UMultiplicities(), value)
                                   : multiplicityAt(surface.VKnots(), surface.VMultiplicities(), value);
    if (present < multiplicity) missing.emplace_back(value, multiplicity - present);
  }
  if (missing.empty()) return;
  std::sort(missing.begin(), missing.end());
  TColStd_Array1OfReal knots(1, static_cast<int>(missing.size()));
  TColStd_Array1OfInteger multiplicities(1, static_cast<int>(missing.size()));
  for (std::size_t i = 0; i < missing.size(); ++i) {
    knots(static_cast<int>(i) + 1) = missing[i].first;
    multiplicities(static_cast<int>(i) + 1) = missing[i].second;
  }
  if (uDirection) {
    surface.InsertUKnots(knots, multiplicities, kKnotTolerance, true);
  } else {
    surface.InsertVKnots(knots, multiplicities, kKnotTolerance, true);
  }
}

}  // namespace

void makeCompatible(std::vector<Handle(Geom_BSplineCurve)>& curves) {
  if (curves.empty()) return;
  // Periodic and clamped curves cannot share one knot vector: mixed, all become clamped
  // (same geometry, same parameters).
  const bool anyPeriodic = std::any_of(curves.begin(), curves.end(), [](const auto& c) { return c->IsPeriodic(); });
  const bool allPeriodic = std::all_of(curves.begin(), curves.end(), [](const auto& c) { return c->IsPeriodic(); });
  if (anyPeriodic && !allPeriodic)
    for (auto& curve : curves)
      if (curve->IsPeriodic()) {
        const double first = curve->FirstParameter(), last = curve->LastParameter();
        curve->SetNotPeriodic();  // may keep knots of the neighbouring periods
        curve->Segment(first, last);
      }
  int degree = 0;
  for (const auto& curve : curves) {
    degree = std::max(degree, curve->Degree());
    requireSameRange(curves.front()->FirstParameter(), curves.front()->LastParameter(), curve->FirstParameter(),
                     curve->LastParameter());
  }
  KnotUnion all;
  for (auto& curve : curves) {
    if (curve->Degree() < degree) curve->IncreaseDegree(degree);
    for (int i = 1; i <= curve->NbKnots(); ++i) all.add(curve->Knot(i), curve->Multiplicity(i));
  }
  for (auto& curve : curves) {
    for (const auto& [value, multiplicity] : all.knots()) {
      const int present = multiplicityAt(curve->Knots(), curve->Multiplicities(), value);
      if (present < multiplicity) curve->InsertKnot(value, multiplicity - present, kKnotTolerance, true);
    }
  }
}

void makeCompatible(std::vector<Handle(Geom_BSplineSurface)>& surfaces) {
  if (surfaces.empty()) return;
  int uDegree = 0, vDegree = 0;
  for (const auto& surface : surfaces) {
    uDegree = std::max(uDegree, surface->UDegree());
    vDegree = std::max(vDegree, surface->VDegree());
  }
  KnotUnion uKnots, vKnots;
  for (auto& surface : surfaces) {
    surface->IncreaseDegree(uDegree, vDegree);
    for (int i = 1; i <= surface->NbUKnots(); ++i) uKnots.add(surface->UKnot(i), surface->UMultiplicity(i));
    for (int i = 1; i <= surface->NbVKnots(); ++i) vKnots.add(surface->VKnot(i), surface->VMultiplicity(i));
  }
  for (auto& surface : surfaces) {
    insertMissing(*surface, uKnots, true);
    insertMissing(*surface, vKnots, false);
  }
}

}  // namespace airshape::geometry
