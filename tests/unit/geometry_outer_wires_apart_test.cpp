// A plane face holding two outer wires (as a Boolean common makes on rare inputs, which OCCT's
// check calls an invalid imbrication of wires) becomes one face per outer wire.
#include <vector>

#include <gtest/gtest.h>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include "airshape/geometry/outer_wires_apart.h"

namespace airshape::geometry {
namespace {

/// A square in the x-y plane, counterclockwise seen from +z (clockwise when `clockwise`).
TopoDS_Wire square(double x, double y, double side, bool clockwise = false) {
  std::vector<gp_Pnt> corners{{x, y, 0}, {x + side, y, 0}, {x + side, y + side, 0}, {x, y + side, 0}};
  if (clockwise) std::swap(corners[1], corners[3]);
  BRepBuilderAPI_MakePolygon polygon;
  for (const gp_Pnt& corner : corners) polygon.Add(corner);
  polygon.Close();
  return polygon.Wire();
}

double areaOf(const TopoDS_Face& face) {
  GProp_GProps properties;
  BRepGProp::SurfaceProperties(face, properties);
  return properties.Mass();
}

TEST(OuterWiresApart, AFaceWithTwoOuterWiresBecomesTwoValidFaces) {
  TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Pln(), square(0, 0, 1)).Face();
  BRep_Builder().Add(face, square(3, 0, 2));
  ASSERT_FALSE(BRepCheck_Analyzer(face).IsValid());
  const std::vector<TopoDS_Face> apart = outerWiresApart(face);
  ASSERT_EQ(apart.size(), 2u);
  double area = 0.0;
  for (const TopoDS_Face& part : apart) {
    EXPECT_TRUE(BRepCheck_Analyzer(part).IsValid());
    area += areaOf(part);
  }
  EXPECT_NEAR(area, 1.0 + 4.0, 1e-12);
}

TEST(OuterWiresApart, AValidFaceWithAHoleStaysAsItIs) {
  TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Pln(), square(0, 0, 4)).Face();
  BRep_Builder().Add(face, square(1, 1, 1, true));
  ASSERT_TRUE(BRepCheck_Analyzer(face).IsValid());
  const std::vector<TopoDS_Face> apart = outerWiresApart(face);
  ASSERT_EQ(apart.size(), 1u);
  EXPECT_TRUE(apart.front().IsSame(face));
  EXPECT_NEAR(areaOf(apart.front()), 16.0 - 1.0, 1e-12);
}

}  // namespace
}  // namespace airshape::geometry
