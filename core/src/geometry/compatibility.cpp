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
  // In a periodic direction the knot ending the period is the one starting it: inserting it
  // there too would insert the same knot twice (OCCT then reads beyond the poles).
  const bool periodic = uDirection ? surface.IsUPeriodic() : surface.IsVPeriodic();
  double u0, u1, v0, v1;
  surface.Bounds(u0, u1, v0, v1);
  const double periodEnd = uDirection ? u1 : v1;
  std::vector<std::pair<double, int>> missing;
  for (const auto& [value, multiplicity] : all.knots()) {
    if (periodic && std::abs(value - periodEnd) <= kKnotTolerance) continue;
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

/// Moves the start of a periodic direction to `start` (the same surface, its period counted
/// from there), so that periodic surfaces whose periods begin elsewhere share one range.
void startPeriodAt(Geom_BSplineSurface& surface, bool uDirection, double start) {
  if (!(uDirection ? surface.IsUPeriodic() : surface.IsVPeriodic())) return;
  double u0, u1, v0, v1;
  surface.Bounds(u0, u1, v0, v1);
  const double first = uDirection ? u0 : v0, period = uDirection ? u1 - u0 : v1 - v0;
  if (std::abs(first - start) <= kKnotTolerance) return;
  // The knot where the new period starts, within the current one.
  double knot = start + std::ceil((first - start) / period) * period;
  if (knot >= first + period - kKnotTolerance) knot -= period;
  if (uDirection) {
    surface.InsertUKnot(knot, 1, kKnotTolerance, false);
    int index = 1;
    while (std::abs(surface.UKnot(index) - knot) > kKnotTolerance) ++index;
    surface.SetUOrigin(index);
  } else {
    surface.InsertVKnot(knot, 1, kKnotTolerance, false);
    int index = 1;
    while (std::abs(surface.VKnot(index) - knot) > kKnotTolerance) ++index;
    surface.SetVOrigin(index);
  }
  const int count = uDirection ? surface.NbUKnots() : surface.NbVKnots();
  TColStd_Array1OfReal knots(1, count);
  if (uDirection)
    surface.UKnots(knots);
  else
    surface.VKnots(knots);
  const double shift = start - knots(1);
  for (int i = 1; i <= count; ++i) knots(i) += shift;
  if (uDirection)
    surface.SetUKnots(knots);
  else
    surface.SetVKnots(knots);
}

/// Every surface raised to the highest degrees in both directions, and knots inserted until
/// all share one knot vector in v, and in u too with `inU`.
void makeSurfacesCompatible(std::vector<Handle(Geom_BSplineSurface)>& surfaces, bool inU) {
  if (surfaces.empty()) return;
  int uDegree = 0, vDegree = 0;
  for (const auto& surface : surfaces) {
    uDegree = std::max(uDegree, surface->UDegree());
    vDegree = std::max(vDegree, surface->VDegree());
  }
  double u0, u1, v0, v1;
  surfaces.front()->Bounds(u0, u1, v0, v1);
  KnotUnion uKnots, vKnots;
  for (auto& surface : surfaces) {
    startPeriodAt(*surface, true, u0);
    startPeriodAt(*surface, false, v0);
    surface->IncreaseDegree(uDegree, vDegree);
    for (int i = 1; i <= surface->NbUKnots(); ++i) uKnots.add(surface->UKnot(i), surface->UMultiplicity(i));
    for (int i = 1; i <= surface->NbVKnots(); ++i) vKnots.add(surface->VKnot(i), surface->VMultiplicity(i));
  }
  for (auto& surface : surfaces) {
    if (inU) insertMissing(*surface, uKnots, true);
    insertMissing(*surface, vKnots, false);
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

void makeCompatible(std::vector<Handle(Geom_BSplineSurface)>& surfaces) { makeSurfacesCompatible(surfaces, true); }

void makeCompatibleAlongV(std::vector<Handle(Geom_BSplineSurface)>& surfaces) {
  makeSurfacesCompatible(surfaces, false);
}

}  // namespace airshape::geometry
