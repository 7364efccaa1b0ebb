// The section of a solid with plane and ruled faces (ruled_solid_section.h), against areas known
// in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <GProp_GProps.hxx>

#include "airshape/geometry/plane_region.h"
#include "airshape/geometry/ruled_sections.h"
#include "airshape/geometry/ruled_solid_section.h"

namespace airshape::geometry {
namespace {

constexpr double kTolerance = 1e-9;

/// The area of a section: its common with a region far larger than it.
double areaOf(const gp_Pln& plane, const PlaneRegion& section) {
  const gp_Ax3& frame = plane.Position();
  const auto corner = [&](double x, double y) {
    return frame.Location().Translated(x * gp_Vec(frame.XDirection()) + y * gp_Vec(frame.YDirection()));
  };
  BRepBuilderAPI_MakePolygon square(corner(-100, -100), corner(100, -100), corner(100, 100), corner(-100, 100), true);
  const auto everything = regionOf(plane, BRepBuilderAPI_MakeFace(plane, square.Wire(), true).Face());
  const auto faces = commonOf(plane, *everything, section, kTolerance);
  EXPECT_TRUE(faces);
  GProp_GProps properties;
  for (const TopoDS_Face& face : *faces) BRepGProp::SurfaceProperties(face, properties, 1e-12);
  return properties.Mass();
}

/// A loft ruled between a square at z = 0 and the same square turned by 30 degrees at z = 2:
/// its side faces are twisted.
struct TwistedLoft {
  std::vector<gp_Pnt> bottom, top;
  RuledSections loft;
  TwistedLoft() {
    for (int k = 0; k < 4; ++k) {
      const double a = M_PI / 2.0 * k, b = a + M_PI / 6.0;
      bottom.emplace_back(std::cos(a), std::sin(a), 0.0);
      top.emplace_back(std::cos(b), std::sin(b), 2.0);
    }
    const auto wire = [](const std::vector<gp_Pnt>& corners) {
      BRepBuilderAPI_MakePolygon polygon(corners[0], corners[1], corners[2], corners[3], true);
      return polygon.Wire();
    };
    loft = ruledThroughSections({wire(bottom), wire(top)});
  }
};

TEST(RuledSolidSection, ObliquePlaneThroughABox) {
  // A unit cube cut by the plane x + z = 1.2: a rectangle 1 by 0.8 sqrt(2).
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1, 1, 1).Shape();
  const gp_Pln plane(gp_Pnt(0.6, 0.5, 0.6), gp_Dir(1, 0, 1));
  const auto section = ruledSolidSection(box, plane, kTolerance);
  ASSERT_TRUE(section);
  ASSERT_EQ(section->size(), 1u);
  EXPECT_NEAR(areaOf(plane, *section), 0.8 * std::sqrt(2.0), 1e-12);
}

TEST(RuledSolidSection, TwistedLoftCutHalfway) {
  // A loft ruled between a square at z = 0 and the same square turned by 30 degrees at z = 2:
  // halfway up, every ruling is cut at its middle, so the section is the square of the
  // corners' midpoints (shoelace area), though the side faces are twisted.
  const TwistedLoft twisted;
  const RuledSections& loft = twisted.loft;
  ASSERT_FALSE(loft.solid.IsNull());
  double twice = 0.0;
  for (int k = 0; k < 4; ++k) {
    const gp_XYZ p = 0.5 * (twisted.bottom[k].XYZ() + twisted.top[k].XYZ()),
                 q = 0.5 * (twisted.bottom[(k + 1) % 4].XYZ() + twisted.top[(k + 1) % 4].XYZ());
    twice += p.X() * q.Y() - q.X() * p.Y();
  }
  const gp_Pln plane(gp_Pnt(0, 0, 1), gp_Dir(0, 0, 1));
  const auto section = ruledSolidSection(loft.solid, plane, kTolerance);
  ASSERT_TRUE(section);
  EXPECT_NEAR(areaOf(plane, *section), 0.5 * twice, 1e-9);
}

TEST(RuledSolidSection, PlaneAlongTheRulingsAgreesWithBooleanCommon) {
  // The same twisted loft cut lengthwise (x = 0.2): the rulings of two side faces run along
  // the plane at some point (their share jumps there); OCCT's Boolean common of the plane with
  // the solid is the independent reference.
  const TwistedLoft twisted;
  const RuledSections& loft = twisted.loft;
  ASSERT_FALSE(loft.solid.IsNull());
  const gp_Pln plane(gp_Pnt(0.2, 0, 0), gp_Dir(1, 0, 0));
  const auto section = ruledSolidSection(loft.solid, plane, kTolerance);
  ASSERT_TRUE(section);
  const TopoDS_Face big = BRepBuilderAPI_MakeFace(plane, -10, 10, -10, 10).Face();
  BRepAlgoAPI_Common common(big, loft.solid);
  ASSERT_TRUE(common.IsDone());
  GProp_GProps reference;
  BRepGProp::SurfaceProperties(common.Shape(), reference, 1e-12);
  EXPECT_NEAR(areaOf(plane, *section), reference.Mass(), 1e-7);
}

TEST(RuledSolidSection, PlaneMissingTheSolidGivesNothingInside) {
  const auto section =
      ruledSolidSection(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), gp_Pln(gp_Pnt(0, 0, 5), gp_Dir(0, 0, 1)), kTolerance);
  ASSERT_TRUE(section);
  EXPECT_TRUE(section->empty());
}

TEST(RuledSolidSection, PlaneInAFaceIsLeftToTheCaller) {
  EXPECT_FALSE(
      ruledSolidSection(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), gp_Pln(gp_Pnt(0, 0, 1), gp_Dir(0, 0, 1)), kTolerance));
}

}  // namespace
}  // namespace airshape::geometry
