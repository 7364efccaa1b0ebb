#include "airshape/geometry/surface_split.h"

#include <algorithm>
#include <cmath>

#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

namespace {

/// Knots closer than this (relative to the v range) are the same knot.
constexpr double kSameKnot = 1e-12;

/// The index (1-based, as OCCT counts) of the knot at `v`, which must be one.
int knotIndexAt(const Geom_BSplineSurface& surface, double v, double tolerance) {
  for (int k = 1; k <= surface.NbVKnots(); ++k)
    if (std::abs(surface.VKnot(k) - v) <= tolerance) return k;
  throw Error(ErrorCode::InvalidArgument, "a site to split a surface at is not one of its knots");
}

/// The part between knots `first` and `last` (1-based) of a surface whose inner knots there
/// have multiplicity of at least the degree: its poles are a contiguous block of columns.
Handle(Geom_BSplineSurface) partBetweenKnots(const Geom_BSplineSurface& whole, int first, int last) {
  const int degree = whole.VDegree();
  // The first pole of the part: the knots' flat position minus the degree, where a knot of
  // multiplicity `degree` starts one pole before its flat position (the surface passes there).
  int flatStart = 0;
  for (int k = 1; k < first; ++k) flatStart += whole.VMultiplicity(k);
  const int firstPole = flatStart + whole.VMultiplicity(first) - degree;  // 1-based
  int innerKnots = 0;
  for (int k = first + 1; k < last; ++k) innerKnots += whole.VMultiplicity(k);
  const int poleCount = degree + 1 + innerKnots;

  const int uPoles = whole.NbUPoles();
  TColgp_Array2OfPnt poles(1, uPoles, 1, poleCount);
  TColStd_Array2OfReal weights(1, uPoles, 1, poleCount);
  for (int i = 1; i <= uPoles; ++i)
    for (int j = 1; j <= poleCount; ++j) {
      poles(i, j) = whole.Pole(i, firstPole + j - 1);
      weights(i, j) = whole.Weight(i, firstPole + j - 1);
    }
  const int vKnotCount = last - first + 1;
  TColStd_Array1OfReal vKnots(1, vKnotCount);
  TColStd_Array1OfInteger vMults(1, vKnotCount);
  for (int k = first; k <= last; ++k) {
    vKnots(k - first + 1) = whole.VKnot(k);
    vMults(k - first + 1) = (k == first || k == last) ? degree + 1 : whole.VMultiplicity(k);
  }
  TColStd_Array1OfReal uKnots(1, whole.NbUKnots());
  TColStd_Array1OfInteger uMults(1, whole.NbUKnots());
  whole.UKnots(uKnots);
  whole.UMultiplicities(uMults);
  if (whole.IsURational() || whole.IsVRational())
    return new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, whole.UDegree(), degree,
                                   whole.IsUPeriodic(), false);
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, whole.UDegree(), degree, whole.IsUPeriodic(),
                                 false);
}

}  // namespace

std::vector<Handle(Geom_BSplineSurface)> splitAlongV(const Geom_BSplineSurface& surface,
                                                     const std::vector<double>& sites) {
  std::vector<Handle(Geom_BSplineSurface)> parts;
  double u0, u1, v0, v1;
  surface.Bounds(u0, u1, v0, v1);
  if (surface.IsVPeriodic()) {
    for (std::size_t k = 0; k + 1 < sites.size(); ++k) {
      auto part = Handle(Geom_BSplineSurface)::DownCast(surface.Copy());
      part->Segment(u0, u1, sites[k], sites[k + 1]);
      parts.push_back(part);
    }
    return parts;
  }
  const double tolerance = kSameKnot * std::max(1.0, v1 - v0);
  auto whole = Handle(Geom_BSplineSurface)::DownCast(surface.Copy());
  const int degree = whole->VDegree();
  // All inner sites at once: one pass over the poles (knot by knot, each would be another).
  std::vector<double> inner;
  for (double site : sites)
    if (site > v0 + tolerance && site < v1 - tolerance) inner.push_back(site);
  if (!inner.empty()) {
    TColStd_Array1OfReal knots(1, static_cast<int>(inner.size()));
    TColStd_Array1OfInteger multiplicities(1, static_cast<int>(inner.size()));
    for (std::size_t i = 0; i < inner.size(); ++i) {
      knots(static_cast<int>(i) + 1) = inner[i];
      multiplicities(static_cast<int>(i) + 1) = degree;
    }
    whole->InsertVKnots(knots, multiplicities, tolerance, false);
  }
  for (std::size_t k = 0; k + 1 < sites.size(); ++k) {
    const double start = std::max(sites[k], v0), end = std::min(sites[k + 1], v1);
    const int first = knotIndexAt(*whole, start, tolerance), last = knotIndexAt(*whole, end, tolerance);
    parts.push_back(partBetweenKnots(*whole, first, last));
  }
  return parts;
}

}  // namespace airshape::geometry
