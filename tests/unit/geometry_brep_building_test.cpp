// Planar caps lie in their boundary's plane, however it is tilted; a boundary that leaves
// its plane gets no cap but an error.
#include <cmath>

#include <gtest/gtest.h>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Plane.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/ruled_loft.h"

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

TEST(BrepBuilding, ARuledLoftIsAValidSolidWithSharedEdges) {
  // Two ellipses of one wire each, 3 apart along z, the second smaller: a frustum-like solid.
  const gp_Vec x(1, 0, 0), y(0, 1, 0);
  const Handle(Geom_BSplineCurve) bottom = ellipse(gp_Pnt(0, 0, 0), x, y);
  const Handle(Geom_BSplineCurve) top = ellipse(gp_Pnt(0, 0, 3), 0.5 * x, 0.5 * y);
  const RuledLoft loft = ruledLoft({bottom}, {top});
  EXPECT_TRUE(BRepCheck_Analyzer(loft.solid).IsValid());
  // A frustum of elliptic caps: h/3 (A1 + A2 + sqrt(A1 A2)), A2 = A1 / 4.
  const double a1 = areaOf(loft.firstCap), a2 = areaOf(loft.lastCap);
  EXPECT_NEAR(a2, a1 / 4.0, 1e-9 * a1);
  EXPECT_NEAR(volumeOf(loft.solid), 3.0 / 3.0 * (a1 + a2 + std::sqrt(a1 * a2)), 1e-9 * a1 * 3.0);
  // Outward: OCCT classifies a point far away as outside.
  BRepClass3d_SolidClassifier outside(loft.solid, gp_Pnt(0, 0, 100), 1e-7);
  EXPECT_EQ(outside.State(), TopAbs_OUT);
  BRepClass3d_SolidClassifier inside(loft.solid, gp_Pnt(0, 0, 1), 1e-7);
  EXPECT_EQ(inside.State(), TopAbs_IN);
}

TEST(BrepBuilding, ARuledLoftBetweenTwoProfilesInOnePlaneIsAFlatRingThatIsKept) {
  // An ellipse and one of half its size around it in the plane z = 1: no volume, but a ring
  // of three quarters of the outer ellipse's area, as a wing steps to a smaller airfoil.
  const gp_Vec x(1, 0, 0), y(0, 1, 0);
  const RuledLoft loft = ruledLoft({ellipse(gp_Pnt(0, 0, 1), x, y)}, {ellipse(gp_Pnt(0, 0, 1), 0.5 * x, 0.5 * y)});
  const double outer = areaOf(loft.firstCap);
  EXPECT_NEAR(volumeOf(loft.solid), 0.0, 1e-12);
  EXPECT_NEAR(areaOf(loft.sides.front()), 0.75 * outer, 1e-9 * outer);
}

/// A lens of two arcs from (0, 0, 0) to (1, 0, 0) in the plane y = 0, turned by `angle`
/// about the vertical line through (1, 0, 0): its upper arc (first to last) and lower arc
/// (last to first, as a loop runs it, here given first to last).
std::vector<Handle(Geom_BSplineCurve)> lens(double angle) {
  std::vector<gp_Pnt> upper, lower;
  for (int i = 0; i <= 16; ++i) {
    const double x = i / 16.0, z = 0.1 * std::sin(M_PI * x);
    const gp_Vec arm(x - 1.0, 0.0, 0.0);
    const gp_Pnt p = gp_Pnt(1.0 + arm.X() * std::cos(angle), arm.X() * std::sin(angle), 0.0);
    upper.emplace_back(p.X(), p.Y(), z);
    lower.emplace_back(p.X(), p.Y(), -z);
  }
  return {interpolateCurve(upper, chordParameters(upper, 0.5), 3),
          interpolateCurve(lower, chordParameters(lower, 0.5), 3)};
}

TEST(BrepBuilding, ARuledLoftBetweenProfilesThatTouchIsValid) {
  // The lenses share their point (1, 0, 0): the side edge there degenerates.
  const RuledLoft loft = ruledLoft(lens(0.0), lens(0.5));
  EXPECT_TRUE(BRepCheck_Analyzer(loft.solid).IsValid());
  ASSERT_EQ(loft.sides.size(), 2u);
  EXPECT_GT(volumeOf(loft.solid), 0.0);
  BRepClass3d_SolidClassifier inside(loft.solid, gp_Pnt(0.3, -0.2, 0.0), 1e-7);
  EXPECT_EQ(inside.State(), TopAbs_IN);
  // Profiles that coincide enclose nothing: an error, not an empty solid.
  EXPECT_THROW(ruledLoft(lens(0.0), lens(0.0)), Error);
}

}  // namespace
}  // namespace airshape::geometry
