#include "airshape/geometry/periodic_curve.h"

#include <algorithm>
#include <cmath>

#include <gp_Vec.hxx>

#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_interpolation.h"

namespace airshape::geometry {

double projectNear(const Geom_BSplineCurve& curve, const gp_Pnt& point, double guess) {
  double t = guess;
  for (int iteration = 0; iteration < 30; ++iteration) {
    gp_Pnt p;
    gp_Vec d1, d2;
    curve.D2(t, p, d1, d2);
    const gp_Vec r(point, p);
    const double slope = r.Dot(d1), curvature = d1.Dot(d1) + r.Dot(d2);
    if (!(curvature > 0.0)) break;
    const double step = slope / curvature;
    t -= step;
    if (!curve.IsPeriodic()) t = std::clamp(t, curve.FirstParameter(), curve.LastParameter());
    if (std::abs(step) < 1e-15) break;
  }
  return t;
}

/// count + 1 parameters of the curve whose points are (nearly) evenly spaced along it: clustered
/// samples, where the parametrisation is slow, would make the interpolant wiggle.
std::vector<double> evenlySpacedParameters(const Geom_BSplineCurve& curve, int count) {
  const int fine = 16 * count;
  const double first = curve.FirstParameter(), last = curve.LastParameter();
  std::vector<double> t(static_cast<std::size_t>(fine) + 1), length(static_cast<std::size_t>(fine) + 1, 0.0);
  gp_Pnt previous = curve.Value(first);
  for (int i = 0; i <= fine; ++i) {
    t[static_cast<std::size_t>(i)] = first + (last - first) * i / fine;
    const gp_Pnt p = curve.Value(t[static_cast<std::size_t>(i)]);
    if (i > 0) length[static_cast<std::size_t>(i)] = length[static_cast<std::size_t>(i) - 1] + p.Distance(previous);
    previous = p;
  }
  std::vector<double> chosen;
  std::size_t j = 0;
  for (int i = 0; i <= count; ++i) {
    const double wanted = length.back() * i / count;
    while (j + 1 < length.size() - 1 && length[j + 1] < wanted) ++j;
    const double share = (wanted - length[j]) / std::max(length[j + 1] - length[j], 1e-300);
    chosen.push_back(t[j] + std::clamp(share, 0.0, 1.0) * (t[j + 1] - t[j]));
  }
  chosen.front() = first;
  chosen.back() = last;
  return chosen;
}

Handle(Geom_BSplineCurve) periodicCopy(const Geom_BSplineCurve& closed, std::vector<double>& parameters) {
  const int count = std::max(256, 4 * closed.NbPoles());
  const std::vector<double> old = evenlySpacedParameters(closed, count);
  std::vector<gp_Pnt> points;
  for (double t : old) points.push_back(closed.Value(t));
  points.back() = points.front();
  const std::vector<double> fresh = chordParameters(points, 1.0);
  Handle(Geom_BSplineCurve) periodic = interpolateCurve(points, fresh, 3, true);
  for (double& t : parameters) {
    const auto upper = std::upper_bound(old.begin(), old.end(), t);
    const std::size_t i =
        std::min<std::size_t>(static_cast<std::size_t>(std::max<long>(upper - old.begin() - 1, 0)), old.size() - 2);
    const double share = (t - old[i]) / (old[i + 1] - old[i]);
    const double guess = fresh[i] + share * (fresh[i + 1] - fresh[i]);
    t = projectNear(*periodic, closed.Value(t), guess);
    t = std::fmod(std::fmod(t, 1.0) + 1.0, 1.0);
    if (t > 1.0 - 1e-12) t = 0.0;
  }
  return periodic;
}

}  // namespace airshape::geometry
