// Faces of one surface put together in its parameter plane (parameter_region.h): the common of
// two trimmed faces of a skin is the face trimmed to their common parameter rectangle.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Tool.hxx>

#include "airshape/geometry/parameter_region.h"
#include "test_area.h"
#include "test_wing_skins.h"

namespace airshape::geometry {
namespace {

/// The skin's face over a rectangle of its parameters.
TopoDS_Face skinOver(double u0, double u1, double v0, double v1) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(test::upperSkin());
  return BRepBuilderAPI_MakeFace(surface, u0, u1, v0, v1, 1e-9).Face();
}

TEST(ParameterRegion, CommonOfTwoFacesOfOneSkin) {
  // Overlapping in u, one within the other in v (their sides at v = 0.2 and 0.8 run together
  // with the other's inside): the common is the face over [0.4, 0.6] x [0.2, 0.8].
  const TopoDS_Face a = skinOver(0.0, 0.6, 0.0, 1.0), b = skinOver(0.4, 1.0, 0.2, 0.8);
  const auto regionA = parameterRegionOf(a), regionB = parameterRegionOf(b);
  ASSERT_TRUE(regionA);
  ASSERT_TRUE(regionB);
  const auto common = commonOf(kParameterPlane, *regionA, *regionB, 1e-12);
  ASSERT_TRUE(common);
  ASSERT_EQ(common->size(), 1u);
  const auto face = faceOnSurface(BRep_Tool::Surface(a), (*common)[0], a);
  ASSERT_TRUE(face);
  EXPECT_NEAR(test::accurateArea(*face), test::accurateArea(skinOver(0.4, 0.6, 0.2, 0.8)), 1e-10);
}

TEST(ParameterRegion, FacesSharingASideHaveNoCommon) {
  const TopoDS_Face a = skinOver(0.0, 0.5, 0.0, 1.0), b = skinOver(0.5, 1.0, 0.0, 1.0);
  const auto common = commonOf(kParameterPlane, *parameterRegionOf(a), *parameterRegionOf(b), 1e-12);
  ASSERT_TRUE(common);
  EXPECT_TRUE(common->empty());
}

}  // namespace
}  // namespace airshape::geometry
