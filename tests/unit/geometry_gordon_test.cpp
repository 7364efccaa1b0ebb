// Gordon surfaces of analytic networks, and networks that cannot be interpolated.
#include <cmath>

#include <gtest/gtest.h>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <gp_Ax3.hxx>

#include "airshape/error.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/gordon_surface.h"
#include "airshape/geometry/skinning.h"

namespace airshape::geometry {
namespace {

using Curves = std::vector<Handle(Geom_BSplineCurve)>;

/// A curve through dense samples of f on [0, 1] (closed when f(0) == f(1)).
template <class F>
Handle(Geom_BSplineCurve) sampledCurve(F f, bool closed = false, int count = 160) {
  std::vector<gp_Pnt> points;
  std::vector<double> parameters;
  for (int i = 0; i <= count; ++i) {
    parameters.push_back(static_cast<double>(i) / count);
    points.push_back(f(parameters.back()));
  }
  if (closed) points.back() = points.front();
  return interpolateCurve(points, parameters, 3, closed);
}

/// Largest distance from samples of a reference surface s(u, v) to the Gordon surface.
template <class S>
double deviation(const Handle(Geom_BSplineSurface) & gordon, S reference) {
  double u1 = 0, u2 = 0, v1 = 0, v2 = 0;
  gordon->Bounds(u1, u2, v1, v2);
  GeomAPI_ProjectPointOnSurf projector;
  projector.Init(gordon, u1, u2, v1, v2);
  double worst = 0.0;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      projector.Perform(reference(i / 20.0, j / 20.0));
      worst = std::max(worst, projector.LowerDistance());
    }
  return worst;
}

TEST(Gordon, ReproducesABSplineSurfaceNetwork) {
  // A smooth B-spline surface interpolating a grid, and the network of its iso-curves
  // through the grid: the Gordon surface interpolates with the same spaces, so it is the
  // same surface again.
  std::vector<std::vector<gp_Pnt>> grid(6);
  std::vector<double> u = {0, 0.2, 0.4, 0.6, 0.8, 1.0}, v = {0, 0.2, 0.4, 0.6, 0.8, 1.0};
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < 6; ++l) grid[k].emplace_back(4.0 * u[l], 3.0 * v[k], 0.4 * std::sin(3 * u[l] + 2 * v[k]));
  const auto uSpace = skinningSpace(u, 3, false), vSpace = skinningSpace(v, 3, false);
  const Handle(Geom_BSplineSurface) reference = interpolateGrid(grid, u, uSpace, v, vSpace);
  Curves profiles, guides;
  for (double vk : v) profiles.push_back(Handle(Geom_BSplineCurve)::DownCast(reference->VIso(vk)));
  for (double ul : u) guides.push_back(Handle(Geom_BSplineCurve)::DownCast(reference->UIso(ul)));
  const GordonSurface gordon = buildGordonSurface(profiles, guides, {1e-6, 1e-8});
  EXPECT_LT(deviation(gordon.surface, [&](double s, double t) { return reference->Value(s, t); }), 1e-6);
}

TEST(Gordon, ReproducesACylinderAndATorus) {
  const double r = 1.5;
  // A closed network on a cylinder: circles as profiles, lines as guides.
  Curves circles, lines;
  for (double z : {0.0, 1.0, 2.5, 4.0})
    circles.push_back(sampledCurve(
        [&](double t) { return gp_Pnt(r * std::cos(2 * M_PI * t), r * std::sin(2 * M_PI * t), z); }, true));
  for (int l = 0; l < 5; ++l) {
    const double a = 2 * M_PI * l / 5;
    lines.push_back(sampledCurve([&](double t) { return gp_Pnt(r * std::cos(a), r * std::sin(a), 4.0 * t); }));
  }
  const GordonSurface cylinder = buildGordonSurface(circles, lines, {1e-6, 1e-8});
  EXPECT_TRUE(cylinder.surface->IsUPeriodic()) << "closed profiles give a periodic direction";
  EXPECT_LT(deviation(cylinder.surface,
                      [&](double s, double t) {
                        return gp_Pnt(r * std::cos(2 * M_PI * s), r * std::sin(2 * M_PI * s), 4.0 * t);
                      }),
            1e-6);

  // A patch of a torus: arcs of both families.
  const double major = 5.0, minor = 1.0;
  auto torus = [&](double s, double t) {
    const double a = 0.8 * s, b = 1.2 * t;
    return gp_Pnt((major + minor * std::cos(b)) * std::cos(a), (major + minor * std::cos(b)) * std::sin(a),
                  minor * std::sin(b));
  };
  Curves arcsU, arcsV;
  for (double t : {0.0, 0.35, 0.7, 1.0}) arcsU.push_back(sampledCurve([&](double s) { return torus(s, t); }));
  for (double s : {0.0, 0.3, 0.5, 0.75, 1.0}) arcsV.push_back(sampledCurve([&](double t) { return torus(s, t); }));
  const GordonSurface patch = buildGordonSurface(arcsU, arcsV, {1e-6, 1e-8});
  EXPECT_LT(deviation(patch.surface, torus), 1e-6);
}

TEST(Gordon, ThreeSectionsAroundAnAxisFollowEveryGuide) {
  // A cowl-like network: three open sections at 0°, 120° and 240° about the x axis, skinned
  // quadratically around, and closed guides around it (many knots each). The skinned sections
  // start their period at 1/6, the guides' at 0; made compatible, the surface must still run
  // along every guide (a knot inserted twice at the period's two ends once left it 0.1 off).
  auto body = [](double s, double turn) {
    const double a = 2 * M_PI * turn, r = (0.5 + 0.2 * s * (1 - s)) * (1 + 0.1 * std::cos(3 * a));
    return gp_Pnt(2.0 * s, r * std::cos(a), r * std::sin(a));
  };
  Curves sections, guides;
  for (double turn : {0.0, 1.0 / 3, 2.0 / 3}) sections.push_back(sampledCurve([&](double s) { return body(s, turn); }));
  for (double s : {0.0, 0.25, 0.5, 0.75, 1.0})
    guides.push_back(sampledCurve([&](double turn) { return body(s, turn); }, true));
  const GordonSurface gordon = buildGordonSurface(sections, guides, {1e-6, 1e-8}, nullptr, 2);
  GeomAPI_ProjectPointOnSurf projector;
  double u1 = 0, u2 = 0, v1 = 0, v2 = 0;
  gordon.surface->Bounds(u1, u2, v1, v2);
  projector.Init(gordon.surface, u1, u2, v1, v2);
  double worst = 0.0;
  for (const auto& guide : guides)
    for (int i = 0; i <= 60; ++i) {
      projector.Perform(
          guide->Value(guide->FirstParameter() + i / 60.0 * (guide->LastParameter() - guide->FirstParameter())));
      worst = std::max(worst, projector.LowerDistance());
    }
  EXPECT_LT(worst, 1e-6);
}

TEST(Gordon, DegenerateNetworksAreErrors) {
  auto line = [](gp_Pnt a, gp_Pnt b) {
    return sampledCurve([=](double t) { return gp_Pnt(a.XYZ() + t * (b.XYZ() - a.XYZ())); }, false, 4);
  };
  const Curves twoProfiles = {line({0, 0, 0}, {1, 0, 0}), line({0, 1, 0}, {1, 1, 0})};
  const Curves twoGuides = {line({0, 0, 0}, {0, 1, 0}), line({1, 0, 0}, {1, 1, 0})};
  EXPECT_NO_THROW(buildGordonSurface(twoProfiles, twoGuides, {}));
  // One profile only.
  EXPECT_THROW(buildGordonSurface({twoProfiles[0]}, twoGuides, {}), Error);
  // A guide that misses a profile names both and the gap.
  const Curves missing = {line({0, 0, 0}, {0, 1, 0}), line({1, 0, 0.5}, {1, 1, 0.5})};
  try {
    buildGordonSurface(twoProfiles, missing, {});
    FAIL() << "a guide missing the profiles must be refused";
  } catch (const Error& error) {
    EXPECT_NE(error.message().find("guide 2 misses profile 1 by 0.5"), std::string::npos) << error.message();
  }
  // Guides that the profiles meet in different orders (neither the same nor reversed).
  const Curves crossed = {line({0.2, 0, 0}, {0.5, 1, 0}), line({0.5, 0, 0}, {0.2, 1, 0}),
                          line({0.8, 0, 0}, {0.8, 1, 0})};
  try {
    buildGordonSurface(twoProfiles, crossed, {});
    FAIL() << "guides out of order must be refused";
  } catch (const Error& error) {
    EXPECT_NE(error.message().find("in another order"), std::string::npos) << error.message();
  }
}

}  // namespace
}  // namespace airshape::geometry
