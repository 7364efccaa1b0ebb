#include "airshape/geometry/kinked_interpolation.h"

#include <algorithm>
#include <cmath>

#include "airshape/error.h"
#include "airshape/geometry/bspline_curve.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/geometry/curve_interpolation.h"

namespace airshape::geometry {

namespace {

template <typename T>
std::vector<T> slice(const std::vector<T>& values, std::size_t first, std::size_t last) {
  return std::vector<T>(values.begin() + static_cast<long>(first), values.begin() + static_cast<long>(last) + 1);
}

/// A copy of the part of `curve` over [from, to].
Handle(Geom_BSplineCurve) trimmed(const Geom_BSplineCurve& curve, double from, double to) {
  Handle(Geom_BSplineCurve) part = Handle(Geom_BSplineCurve)::DownCast(curve.Copy());
  if (part->IsPeriodic()) part->SetNotPeriodic();
  part->Segment(from, to);
  return part;
}

/// The curve with its parameter range moved linearly onto [from, to].
Handle(Geom_BSplineCurve) withRange(Handle(Geom_BSplineCurve) curve, double from, double to) {
  setParameterRange(*curve, from, to);
  return curve;
}

}  // namespace

Handle(Geom_BSplineCurve)
    interpolateWithCorners(const std::vector<gp_Pnt>& points, const std::vector<double>& parameters,
                           std::vector<int> kinks, bool closed) {
  const int last = static_cast<int>(points.size()) - 1;
  std::sort(kinks.begin(), kinks.end());
  kinks.erase(std::unique(kinks.begin(), kinks.end()), kinks.end());
  for (int kink : kinks)
    if (kink < 0 || kink > last) throw Error(ErrorCode::InvalidModel, "a kink index lies outside the point list");
  const bool smoothSeam = closed && (kinks.empty() || (kinks.front() != 0 && kinks.back() != last));
  if (smoothSeam && kinks.empty()) return interpolateCurve(points, parameters, 3, true);
  if (!smoothSeam) {
    if (kinks.empty() || kinks.front() != 0) kinks.insert(kinks.begin(), 0);
    if (kinks.back() != last) kinks.push_back(last);
  }
  std::vector<Handle(Geom_BSplineCurve)> runs;
  for (std::size_t i = 1; i < kinks.size(); ++i) {
    const auto from = static_cast<std::size_t>(kinks[i - 1]), to = static_cast<std::size_t>(kinks[i]);
    runs.push_back(interpolateCurve(slice(points, from, to), slice(parameters, from, to), 3));
  }
  if (smoothSeam) {
    // The run from the last corner over the seam to the first corner, as one curve on
    // parameters that continue below 0, split at the seam and its first part moved to the end.
    const auto lastKink = static_cast<std::size_t>(kinks.back()), firstKink = static_cast<std::size_t>(kinks.front());
    const double period = parameters.back() - parameters.front();
    std::vector<gp_Pnt> wrapPoints = slice(points, lastKink, points.size() - 1);
    std::vector<double> wrapParameters;
    for (std::size_t i = lastKink; i < points.size(); ++i) wrapParameters.push_back(parameters[i] - period);
    for (std::size_t i = 1; i <= firstKink; ++i) {
      wrapPoints.push_back(points[i]);
      wrapParameters.push_back(parameters[i]);
    }
    const auto wrap = interpolateCurve(wrapPoints, wrapParameters, 3);
    const double seam = parameters.front();
    runs.insert(runs.begin(), trimmed(*wrap, seam, wrap->LastParameter()));
    runs.push_back(
        withRange(trimmed(*wrap, wrap->FirstParameter(), seam), wrap->FirstParameter() + period, parameters.back()));
  }
  return concatenateCurves(runs);
}

Handle(Geom_BSplineCurve)
    reparametrisePiecewiseLinearly(const Geom_BSplineCurve& curve, const std::vector<double>& from,
                                   const std::vector<double>& to) {
  constexpr double kSameSlope = 1e-12, kSameKnot = 1e-12;
  if (from.size() != to.size() || from.size() < 2)
    throw Error(ErrorCode::InvalidArgument, "a parameter map needs as many new parameters as old, at least two");
  for (std::size_t i = 1; i < from.size(); ++i)
    if (!(from[i] > from[i - 1]) || !(to[i] > to[i - 1]))
      throw Error(ErrorCode::InvalidModel, "the parameter map does not increase along the points");
  // Pieces between the places where the map bends, each moved linearly onto its new range.
  auto slope = [&](std::size_t i) { return (to[i] - to[i - 1]) / (from[i] - from[i - 1]); };
  std::vector<Handle(Geom_BSplineCurve)> pieces;
  std::size_t start = 0;
  for (std::size_t i = 1; i < from.size(); ++i) {
    const bool bends = i + 1 < from.size() && std::abs(slope(i + 1) - slope(i)) > kSameSlope * std::abs(slope(i));
    if (!bends && i + 1 < from.size()) continue;
    pieces.push_back(withRange(trimmed(curve, from[start], from[i]), to[start], to[i]));
    start = i;
  }
  Handle(Geom_BSplineCurve) result = concatenateCurves(pieces);
  for (std::size_t i = 1; i + 1 < to.size(); ++i) result->InsertKnot(to[i], 1, kSameKnot, false);
  return result;
}

}  // namespace airshape::geometry
