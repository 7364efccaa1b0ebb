#include "isotensoid_meridian.h"

#include <cmath>
#include <vector>

#include <GeomAPI_PointsToBSpline.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include "airshape/error.h"

namespace airshape::tank {

namespace {

/// A point of the meridian: its distance along the axis from the cylinder, and its radius.
struct MeridianStep {
  double depth;
  double radius;
};

/// The steps from the cylinder towards the opening. The first step repeats the cylinder's
/// edge (the reference records the start before stepping), which the approximation keeps.
std::vector<MeridianStep> netting(double cylinderRadius, double openingRadius) {
  constexpr int kSteps = 50;
  const double dPhi = 1.0 / kSteps;
  std::vector<MeridianStep> steps = {{0.0, cylinderRadius}};
  double phi = 0.0, depth = 0.0, radius = cylinderRadius, dr = 0.0;
  double tanAlpha = std::tan(std::asin(openingRadius / cylinderRadius));
  while (tanAlpha * tanAlpha < 2.0 && radius > 1.22 * openingRadius && dr >= 0.0) {
    steps.push_back({depth, radius});
    phi += dPhi;
    tanAlpha = std::tan(std::asin(openingRadius / steps.back().radius));
    const double curvatureRadius = radius / (std::cos(phi) * (2.0 - tanAlpha * tanAlpha));
    dr = curvatureRadius * dPhi * std::sin(phi);
    radius -= dr;
    depth += curvatureRadius * dPhi * std::cos(phi);
  }
  return steps;
}

}  // namespace

Handle(Geom_BSplineCurve) isotensoidMeridian(double cylinderRadius, double polarOpeningRadius) {
  std::vector<MeridianStep> steps = netting(cylinderRadius, polarOpeningRadius);
  if (steps.size() < 3) throw Error(ErrorCode::InvalidModel, "the polar opening is too large for an isotensoid dome");
  // Straight on to the opening along the last step's slope, in four equal steps.
  const MeridianStep last = steps.back(), before = steps[steps.size() - 2];
  const double slope = (last.radius - before.radius) / (last.depth - before.depth);
  const double dRadius = (polarOpeningRadius - last.radius) / 4.0;
  for (int i = 1; i <= 4; ++i) steps.push_back({last.depth + i * dRadius / slope, last.radius + i * dRadius});
  const double depth = steps.back().depth;
  TColgp_Array1OfPnt points(1, static_cast<int>(steps.size()));
  for (std::size_t i = 0; i < steps.size(); ++i)
    points.SetValue(static_cast<int>(i + 1), gp_Pnt(depth - steps[i].depth, 0.0, steps[i].radius));
  // Approximated from the cylinder on, as the reference does (the approximation depends on
  // the order of the points), then turned to run from the opening.
  GeomAPI_PointsToBSpline approximation(points);
  if (!approximation.IsDone()) throw Error(ErrorCode::InvalidModel, "the isotensoid dome cannot be approximated");
  Handle(Geom_BSplineCurve) meridian = approximation.Curve();
  meridian->Reverse();
  return meridian;
}

}  // namespace airshape::tank
