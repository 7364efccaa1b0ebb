// The profile in a section's plane (section_profile.h): the skins' edges there, closed straight
// across a blunt trailing edge.
#include <gtest/gtest.h>

#include <cmath>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Tool.hxx>

#include "airshape/geometry/plane_region.h"
#include "airshape/geometry/section_profile.h"
#include "test_area.h"
#include "test_wing_skins.h"

namespace airshape::geometry {
namespace {

TEST(SectionProfile, RootProfileClosedStraightAcrossTheBluntEdge) {
  // The plane of the root (y = 0): the skins' root edges and the straight line across the
  // blunt trailing edge; its area against Green's theorem summed densely along the skins.
  const TopoDS_Face upper = test::upperSkin(), lower = test::lowerSkin();
  const gp_Pln root(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0));
  const auto profile = profileInPlane(upper, lower, root, 1e-9);
  ASSERT_TRUE(profile);
  BRepBuilderAPI_MakePolygon square(gp_Pnt(-5, 0, -5), gp_Pnt(5, 0, -5), gp_Pnt(5, 0, 5), gp_Pnt(-5, 0, 5), true);
  const auto everything = regionOf(root, BRepBuilderAPI_MakeFace(root, square.Wire(), true).Face());
  const auto faces = commonOf(root, *profile, *everything, 1e-9);
  ASSERT_TRUE(faces);
  ASSERT_EQ(faces->size(), 1u);
  // Twice the area: the integral of x dz - z dx round the profile (upper from the leading edge
  // to the trailing edge, across, lower back).
  const auto along = [](const TopoDS_Face& face, bool backwards) {
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    constexpr int kSteps = 200000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
      const double a = (backwards ? kSteps - i : i) / double(kSteps),
                   b = (backwards ? kSteps - i - 1 : i + 1) / double(kSteps);
      const gp_Pnt p = surface->Value(a, 0.0), q = surface->Value(b, 0.0);
      sum += p.X() * q.Z() - q.X() * p.Z();
    }
    return sum;
  };
  const double across = test::kUpperRoot.X() * test::kLowerRoot.Z() - test::kLowerRoot.X() * test::kUpperRoot.Z();
  const double twice = along(upper, false) + across + along(lower, true);
  EXPECT_NEAR(test::accurateArea((*faces)[0]), std::abs(0.5 * twice), 1e-9);
}

TEST(SectionProfile, PlaneBetweenSectionsHasNone) {
  const TopoDS_Face upper = test::upperSkin(), lower = test::lowerSkin();
  EXPECT_FALSE(profileInPlane(upper, lower, gp_Pln(gp_Pnt(0, 0.5, 0), gp_Dir(0, 1, 0)), 1e-9));
}

}  // namespace
}  // namespace airshape::geometry
