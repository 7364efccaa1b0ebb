// A large skin cut down to the knot spans near a small region, as a Boolean section gets it:
// the same surface and parameters, fewer spans, every point of the skin in the region kept.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/geometry/faces_near.h"
#include "sheet_of_many_spans.h"

namespace airshape::geometry {
namespace {

/// A wavy sheet over [0, 10] × [0, 1]: 40 × 4 cubic spans, uniform knots.
Handle(Geom_BSplineSurface) wavySheet() {
  return test::sheetOfManySpans([](double x, double y) { return 0.2 * std::sin(4.2 * x + 12.0 * y); });
}

std::vector<TopoDS_Face> facesOf(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next())
    faces.push_back(TopoDS::Face(face.Current()));
  return faces;
}

TEST(FacesNear, ASkinIsCutDownToTheSpansNearTheRegionAndKeepsItsPointsThere) {
  const Handle(Geom_BSplineSurface) sheet = wavySheet();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(sheet, 1e-7).Face();
  Bnd_Box region;
  region.Update(4.0, -1.0, -1.0, 5.0, 2.0, 1.0);  // x from 4 to 5: a tenth of the sheet
  const std::vector<TopoDS_Face> near = facesOf(facesNear(face, {region}));
  ASSERT_EQ(near.size(), 1u);
  const Handle(Geom_BSplineSurface) part = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(near.front()));
  ASSERT_FALSE(part.IsNull());
  EXPECT_LT(part->NbUKnots() - 1, 12);  // the spans reaching x in [4, 5], not all 40
  double u0, u1, v0, v1;
  part->Bounds(u0, u1, v0, v1);
  EXPECT_LE(u0, 16.0);  // x = 4 at u = 16 (poles evenly spread): kept
  EXPECT_GE(u1, 20.0);
  for (double u = 16.0; u <= 20.0; u += 0.5)  // the same points at the same parameters
    for (double v = 0.0; v <= 4.0; v += 0.5) EXPECT_LT(part->Value(u, v).Distance(sheet->Value(u, v)), 1e-12);
}

TEST(FacesNear, AFaceAwayFromTheRegionIsLeftOutAndOneInsideIsKeptWhole) {
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(wavySheet(), 1e-7).Face();
  Bnd_Box far, around;
  far.Update(20.0, 20.0, 20.0, 21.0, 21.0, 21.0);
  around.Update(-1.0, -1.0, -1.0, 11.0, 2.0, 1.0);
  EXPECT_TRUE(facesOf(facesNear(face, {far})).empty());
  const std::vector<TopoDS_Face> whole = facesOf(facesNear(face, {far, around}));
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_TRUE(whole.front().IsSame(face));
}

}  // namespace
}  // namespace airshape::geometry
