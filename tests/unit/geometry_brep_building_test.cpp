// Planar caps lie in their boundary's plane, however it is tilted; a boundary that leaves
// its plane gets no cap but an error.
#include <cmath>

#include <gtest/gtest.h>
#include <BRep_Tool.hxx>
#include <Geom_Plane.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/curve_interpolation.h"

namespace airshape::geometry {
namespace {

/// The ellipse with half-axes 2 and 1 in the plane through `centre` spanned by `a` and `b`
/// (unit vectors), through `count` points, with `lift` added to every other point along a × b.
Handle(Geom_BSplineCurve) ellipse(const gp_Pnt& centre, const gp_Vec& a, const gp_Vec& b, double lift = 0.0) {
  constexpr int kCount = 24;
  std::vector<gp_Pnt> points;
  const gp_Vec normal = a.Crossed(b);
  for (int i = 0; i <= kCount; ++i) {
    const double t = 2.0 * M_PI * i / kCount;
    points.push_back(centre.Translated(2.0 * std::cos(t) * a + std::sin(t) * b + (i % 2 ? lift : 0.0) * normal));
  }
  points.back() = points.front();
  return interpolateCurve(points, chordParameters(points, 0.5), 3, true);
}

TEST(BrepBuilding, APlanarCapLiesInItsBoundarysPlane) {
  const gp_Vec a = gp_Vec(1.0, 2.0, 0.5).Normalized(), b = a.Crossed(gp_Vec(0.0, 0.0, 1.0)).Normalized();
  const TopoDS_Face cap = planarFace({ellipse(gp_Pnt(30.0, -4.0, 2.0), a, b)});
  const auto plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(cap));
  ASSERT_FALSE(plane.IsNull());
  EXPECT_NEAR(std::abs(gp_Vec(plane->Position().Direction()).Dot(a.Crossed(b))), 1.0, 1e-12);
  EXPECT_NEAR(plane->Pln().Distance(gp_Pnt(30.0, -4.0, 2.0)), 0.0, 1e-12);
  EXPECT_NEAR(areaOf(cap), 2.0 * M_PI, 2e-3);  // the interpolated ellipse, nearly
}

TEST(BrepBuilding, ABoundaryThatLeavesItsPlaneIsAnError) {
  EXPECT_THROW(planarFace({ellipse(gp_Pnt(0, 0, 0), gp_Vec(1, 0, 0), gp_Vec(0, 1, 0), 0.05)}), Error);
}

}  // namespace
}  // namespace airshape::geometry
