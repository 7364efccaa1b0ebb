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
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/geometry/faces_near.h"

namespace airshape::geometry {
namespace {

/// A wavy sheet over [0, 10] × [0, 1]: 40 × 4 cubic spans, uniform knots.
Handle(Geom_BSplineSurface) wavySheet() {
  constexpr int kUPoles = 43, kVPoles = 7;
  TColgp_Array2OfPnt poles(1, kUPoles, 1, kVPoles);
  for (int i = 1; i <= kUPoles; ++i)
    for (int j = 1; j <= kVPoles; ++j)
      poles(i, j) = gp_Pnt(10.0 * (i - 1) / (kUPoles - 1), (j - 1) / (kVPoles - 1.0), 0.2 * std::sin(i + 2.0 * j));
  TColStd_Array1OfReal uKnots(1, 41), vKnots(1, 5);
  TColStd_Array1OfInteger uMultiplicities(1, 41), vMultiplicities(1, 5);
  for (int i = 1; i <= 41; ++i) uKnots(i) = i - 1, uMultiplicities(i) = (i == 1 || i == 41) ? 4 : 1;
  for (int i = 1; i <= 5; ++i) vKnots(i) = i - 1, vMultiplicities(i) = (i == 1 || i == 5) ? 4 : 1;
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMultiplicities, vMultiplicities, 3, 3);
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
