#include "airshape/geometry/curve_fit.h"

#include <vector>

#include <GeomAPI_Interpolate.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfBoolean.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfVec.hxx>
#include <TColgp_HArray1OfPnt.hxx>

namespace airshape::geometry {

namespace {

constexpr int kStartIntervals = 4;
constexpr int kDeepestHalving = 24;
constexpr int kSmoothRounds = 6;

/// Adds to `nodes` the samples strictly between `a` and `b` that make the cubic Hermite
/// interpolant follow the curve within the tolerance, and to `middles` the samples it was
/// checked at.
bool refine(const CurveSampler& sample, const CurveSample& a, const CurveSample& b, double tolerance, int depth,
            std::vector<CurveSample>& nodes, std::vector<CurveSample>& middles) {
  const std::optional<CurveSample> middle = sample(0.5 * (a.t + b.t), a, b);
  if (!middle) return false;
  // The cubic Hermite interpolant's middle: (Pa + Pb) / 2 + h (Ta - Tb) / 8.
  const gp_XYZ cubic = 0.5 * (a.point.XYZ() + b.point.XYZ()) + ((b.t - a.t) / 8.0) * (a.tangent - b.tangent).XYZ();
  if ((cubic - middle->point.XYZ()).Modulus() <= tolerance) {
    middles.push_back(*middle);
    return true;
  }
  if (depth >= kDeepestHalving) return false;
  if (!refine(sample, a, *middle, tolerance, depth + 1, nodes, middles)) return false;
  nodes.push_back(*middle);
  return refine(sample, *middle, b, tolerance, depth + 1, nodes, middles);
}

/// Whether the curve passes within the tolerance of each sample.
bool within(const Handle(Geom_BSplineCurve) & curve, const std::vector<CurveSample>& samples, double tolerance) {
  for (const CurveSample& sample : samples)
    if (curve->Value(sample.t).Distance(sample.point) > tolerance) return false;
  return true;
}

/// The C2 cubic through the nodes, with more nodes where it strays from the curve by more than
/// the tolerance at an interval's middle (`middles[i]` lies between `nodes[i]` and
/// `nodes[i + 1]`); null when it does not keep to the curve after a few such rounds.
///
/// The C2 cubic is preferred to the Hermite cubic, although it may need a few more samples:
/// the Hermite cubic's double knots end a C2 piece at every sample, and OCCT's curve–surface
/// intersection treats each such piece on its own, sampling the whole surface once per piece.
/// A structural model's join of CPACS_30_D250_10.xml's tip took 10 s with Hermite outlines.
Handle(Geom_BSplineCurve) smoothThrough(const CurveSampler& sample, std::vector<CurveSample> nodes,
                                        std::vector<CurveSample> middles, double tolerance) {
  for (int round = 0; round < kSmoothRounds; ++round) {
    Handle(Geom_BSplineCurve) smooth = cubicThrough(nodes, false);
    if (smooth.IsNull()) return nullptr;
    std::vector<CurveSample> moreNodes{nodes.front()}, moreMiddles;
    bool strayed = false;
    for (std::size_t i = 0; i < middles.size(); ++i) {
      const CurveSample& middle = middles[i];
      if (smooth->Value(middle.t).Distance(middle.point) > tolerance) {
        strayed = true;
        const std::optional<CurveSample> left = sample(0.5 * (nodes[i].t + middle.t), nodes[i], middle);
        const std::optional<CurveSample> right = sample(0.5 * (middle.t + nodes[i + 1].t), middle, nodes[i + 1]);
        if (!left || !right) return nullptr;
        moreMiddles.push_back(*left);
        moreNodes.push_back(middle);
        moreMiddles.push_back(*right);
      } else {
        moreMiddles.push_back(middle);
      }
      moreNodes.push_back(nodes[i + 1]);
    }
    if (!strayed) return smooth;
    nodes.swap(moreNodes);
    middles.swap(moreMiddles);
  }
  return nullptr;
}

}  // namespace

Handle(Geom_BSplineCurve) straightCurve(const gp_Pnt& from, const gp_Pnt& to) {
  TColgp_Array1OfPnt poles(1, 2);
  poles.SetValue(1, from);
  poles.SetValue(2, to);
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, from.Distance(to));
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(2);
  return new Geom_BSplineCurve(poles, knots, multiplicities, 1);
}

Handle(Geom_BSplineCurve) cubicThrough(const std::vector<CurveSample>& nodes, bool everyDerivative) {
  const int count = static_cast<int>(nodes.size());
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, count);
  Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, count);
  for (int i = 0; i < count; ++i) {
    points->SetValue(i + 1, nodes[i].point);
    parameters->SetValue(i + 1, nodes[i].t);
  }
  GeomAPI_Interpolate interpolation(points, parameters, false, 1e-15);
  if (everyDerivative) {
    TColgp_Array1OfVec tangents(1, count);
    Handle(TColStd_HArray1OfBoolean) flags = new TColStd_HArray1OfBoolean(1, count);
    for (int i = 0; i < count; ++i) {
      tangents.SetValue(i + 1, nodes[i].tangent);
      flags->SetValue(i + 1, true);
    }
    interpolation.Load(tangents, flags, false);
  } else {
    interpolation.Load(nodes.front().tangent, nodes.back().tangent, false);
  }
  interpolation.Perform();
  return interpolation.IsDone() ? interpolation.Curve() : nullptr;
}

Handle(Geom_BSplineCurve)
    fittedCurve(const CurveSampler& sample, const CurveSample& first, const CurveSample& last, double tolerance) {
  std::vector<CurveSample> start;
  CurveSample previous = first;
  for (int i = 0; i <= kStartIntervals; ++i) {
    const double t = first.t + (last.t - first.t) * i / kStartIntervals;
    const std::optional<CurveSample> next = sample(t, previous, previous);
    if (!next) return nullptr;
    start.push_back(previous = *next);
  }
  // The ends are the given points exactly, so that neighbouring curves meet where they should.
  start.front().point = first.point;
  start.back().point = last.point;
  std::vector<CurveSample> nodes{start.front()}, middles;
  for (int i = 0; i < kStartIntervals; ++i) {
    if (!refine(sample, start[i], start[i + 1], tolerance, 0, nodes, middles)) return nullptr;
    nodes.push_back(start[i + 1]);
  }
  Handle(Geom_BSplineCurve) smooth = smoothThrough(sample, nodes, middles, tolerance);
  if (!smooth.IsNull()) return smooth;
  Handle(Geom_BSplineCurve) hermite = cubicThrough(nodes, true);
  return !hermite.IsNull() && within(hermite, middles, tolerance) ? hermite : nullptr;
}

}  // namespace airshape::geometry
