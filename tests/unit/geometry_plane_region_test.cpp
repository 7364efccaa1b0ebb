// The common of two planar regions made from their boundaries (plane_region.h), against areas
// known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepGProp.hxx>
#include <GC_MakeCircle.hxx>
#include <GProp_GProps.hxx>
#include <GeomConvert.hxx>
#include <gp_Ax2.hxx>

#include "airshape/geometry/curve_fit.h"
#include "airshape/geometry/plane_region.h"

namespace airshape::geometry {
namespace {

const gp_Pln kPlane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
constexpr double kTolerance = 1e-9;

/// The region inside a polygon of (x, y) corners, counterclockwise.
PlaneRegion polygon(const std::vector<std::pair<double, double>>& corners) {
  PlaneLoop loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto& [x0, y0] = corners[i];
    const auto& [x1, y1] = corners[(i + 1) % corners.size()];
    loop.push_back(planeCurve(kPlane, straightCurve(gp_Pnt(x0, y0, 0), gp_Pnt(x1, y1, 0))));
  }
  return {loop};
}

/// The disk of a radius about (x, y), its circle as one rational B-spline.
PlaneRegion disk(double x, double y, double radius) {
  const Handle(Geom_Circle) circle = GC_MakeCircle(gp_Ax2(gp_Pnt(x, y, 0), gp_Dir(0, 0, 1)), radius).Value();
  return {{planeCurve(kPlane, GeomConvert::CurveToBSplineCurve(circle))}};
}

double areaOf(const std::vector<TopoDS_Face>& faces) {
  GProp_GProps properties;
  for (const TopoDS_Face& face : faces) BRepGProp::SurfaceProperties(face, properties, 1e-12);
  return properties.Mass();
}

TEST(PlaneRegion, SquareAndDiskOverlapInAQuarterDisk) {
  const auto faces = commonOf(kPlane, polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), disk(1, 1, 0.8), kTolerance);
  ASSERT_TRUE(faces);
  ASSERT_EQ(faces->size(), 1u);
  EXPECT_NEAR(areaOf(*faces), M_PI * 0.64 / 4.0, 1e-9);
}

TEST(PlaneRegion, OrderOfTheRegionsDoesNotMatter) {
  const auto faces = commonOf(kPlane, disk(1, 1, 0.8), polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), kTolerance);
  ASSERT_TRUE(faces);
  EXPECT_NEAR(areaOf(*faces), M_PI * 0.64 / 4.0, 1e-9);
}

TEST(PlaneRegion, TwoDisksOverlapInALens) {
  // Unit disks one radius apart: the lens 2 pi / 3 - sqrt(3) / 2.
  const auto faces = commonOf(kPlane, disk(0, 0, 1), disk(1, 0, 1), kTolerance);
  ASSERT_TRUE(faces);
  ASSERT_EQ(faces->size(), 1u);
  EXPECT_NEAR(areaOf(*faces), 2.0 * M_PI / 3.0 - std::sqrt(3.0) / 2.0, 1e-9);
}

TEST(PlaneRegion, ConcaveRegionGivesTwoFaces) {
  // A "C" open to the right, crossed by a band: two unit squares.
  const PlaneRegion letter = polygon({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {3, 2}, {3, 3}, {0, 3}});
  const auto faces = commonOf(kPlane, letter, polygon({{2, -1}, {4, -1}, {4, 4}, {2, 4}}), kTolerance);
  ASSERT_TRUE(faces);
  ASSERT_EQ(faces->size(), 2u);
  EXPECT_NEAR(areaOf({(*faces)[0]}), 1.0, 1e-12);
  EXPECT_NEAR(areaOf({(*faces)[1]}), 1.0, 1e-12);
}

TEST(PlaneRegion, RegionInsideTheOtherIsItself) {
  const auto faces = commonOf(kPlane, disk(0, 0, 0.5), polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}), kTolerance);
  ASSERT_TRUE(faces);
  ASSERT_EQ(faces->size(), 1u);
  EXPECT_NEAR(areaOf(*faces), M_PI * 0.25, 1e-9);
}

TEST(PlaneRegion, RegionsApartHaveNoCommon) {
  const auto faces = commonOf(kPlane, disk(0, 0, 1), disk(3, 0, 1), kTolerance);
  ASSERT_TRUE(faces);
  EXPECT_TRUE(faces->empty());
}

TEST(PlaneRegion, SquaresSharingASideOnlyTouch) {
  // The shared side has the squares on either side: no common.
  const auto faces = commonOf(kPlane, polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}),
                              polygon({{1, 0}, {2, 0}, {2, 1}, {1, 1}}), kTolerance);
  ASSERT_TRUE(faces);
  EXPECT_TRUE(faces->empty());
}

TEST(PlaneRegion, BoundariesRunningTogetherAreFollowedOnce) {
  // Two strips of one band, overlapping in the middle: their bottom and top sides run
  // together there.
  const auto faces = commonOf(kPlane, polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}}),
                              polygon({{1, 0}, {3, 0}, {3, 1}, {1, 1}}), kTolerance);
  ASSERT_TRUE(faces);
  ASSERT_EQ(faces->size(), 1u);
  EXPECT_NEAR(areaOf(*faces), 1.0, 1e-12);
}

TEST(PlaneRegion, RegionInACornerOfTheOther) {
  // The small square shares two sides with the large one: the common is the small square.
  const auto faces = commonOf(kPlane, polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}}),
                              polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), kTolerance);
  ASSERT_TRUE(faces);
  ASSERT_EQ(faces->size(), 1u);
  EXPECT_NEAR(areaOf(*faces), 1.0, 1e-12);
}

TEST(PlaneRegion, FaceWhoseWireRunsClockwiseGivesItsInside) {
  BRepBuilderAPI_MakePolygon clockwise(gp_Pnt(0, 1, 0), gp_Pnt(1, 1, 0), gp_Pnt(1, 0, 0), gp_Pnt(0, 0, 0), true);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(kPlane, clockwise.Wire(), true).Face();
  const auto region = regionOf(kPlane, face);
  ASSERT_TRUE(region);
  const auto faces = commonOf(kPlane, *region, polygon({{0.5, -1}, {2, -1}, {2, 2}, {0.5, 2}}), kTolerance);
  ASSERT_TRUE(faces);
  EXPECT_NEAR(areaOf(*faces), 0.5, 1e-12);
}

}  // namespace
}  // namespace airshape::geometry
