// Coons patches and rows of them: boundaries kept, orientation as documented, and the
// Coons blending (3t² − 2t³) in between.
#include <cmath>

#include <gtest/gtest.h>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include "airshape/error.h"
#include "airshape/geometry/coons_patches.h"

namespace airshape::geometry {
namespace {

/// A cubic Bézier from a to b whose inner poles are lifted by `lift` in z.
Handle(Geom_BSplineCurve) arc(const gp_Pnt& a, const gp_Pnt& b, double lift, double first = 0.0, double last = 1.0) {
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = a;
  poles(2) = gp_Pnt(a.XYZ() * (2.0 / 3.0) + b.XYZ() / 3.0 + gp_XYZ(0, 0, lift));
  poles(3) = gp_Pnt(a.XYZ() / 3.0 + b.XYZ() * (2.0 / 3.0) + gp_XYZ(0, 0, lift));
  poles(4) = b;
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger multiplicities(1, 2);
  knots(1) = first, knots(2) = last;
  multiplicities(1) = multiplicities(2) = 4;
  return new Geom_BSplineCurve(poles, knots, multiplicities, 3);
}

/// The rounded rows of two profiles and three guides that meet them at the profiles'
/// parameters 0, 0.25 and 1 and at their own ends.
std::vector<Handle(Geom_BSplineSurface)> roundedRows(const std::vector<Handle(Geom_BSplineCurve)>& profiles,
                                                     const std::vector<Handle(Geom_BSplineCurve)>& guides) {
  KnownCrossings crossings;
  crossings.profileParameters.resize(2, 3);
  crossings.profileParameters << 0.0, 0.25, 1.0, 0.0, 0.25, 1.0;
  crossings.guideParameters.resize(2, 3);
  crossings.guideParameters << 0.0, 0.0, 0.0, 1.0, 1.0, 1.0;
  return buildCoonsPatchRows(profiles, guides, crossings,
                             [](std::size_t, std::size_t) { return PatchBlending::Rounded; });
}

TEST(CoonsPatch, BoundariesAtTheirNormalisedParameters) {
  const gp_Pnt a(0, 0, 0), b(2, 0, 0), c(2, 1, 0), d(0, 1, 0);
  const auto bottom = arc(a, b, 0.2, 3.0, 5.0), right = arc(b, c, 1.0), top = arc(d, c, -0.1), left = arc(a, d, 0.0);
  const auto patch = coonsPatch(bottom, right, top, left, PatchBlending::Rounded);
  for (double t : {0.0, 0.3, 0.7, 1.0}) {
    EXPECT_LT(patch->Value(t, 0.0).Distance(bottom->Value(3.0 + 2.0 * t)), 1e-12);
    EXPECT_LT(patch->Value(t, 1.0).Distance(top->Value(t)), 1e-12);
    EXPECT_LT(patch->Value(0.0, t).Distance(left->Value(t)), 1e-12);
    EXPECT_LT(patch->Value(1.0, t).Distance(right->Value(t)), 1e-12);
  }
  // Only the right side is lifted (by 0.75 at its middle): inside, the lift fades with the
  // Coons blend 3u² − 2u³ rather than linearly.
  const auto flat = coonsPatch(arc(a, b, 0.0), arc(b, c, 1.0), arc(d, c, 0.0), arc(a, d, 0.0), PatchBlending::Rounded);
  for (double u : {0.25, 0.5, 0.75}) EXPECT_NEAR(flat->Value(u, 0.5).Z(), 0.75 * (3 * u * u - 2 * u * u * u), 1e-12);
  // Bilinear blending fades it linearly.
  const auto bilinear =
      coonsPatch(arc(a, b, 0.0), arc(b, c, 1.0), arc(d, c, 0.0), arc(a, d, 0.0), PatchBlending::Bilinear);
  for (double u : {0.25, 0.5, 0.75}) EXPECT_NEAR(bilinear->Value(u, 0.5).Z(), 0.75 * u, 1e-12);
}

TEST(CoonsPatchRows, CellsSitSideBySide) {
  // Two straight profiles along x and three guides along y: two cells per row.
  std::vector<Handle(Geom_BSplineCurve)> profiles = {arc(gp_Pnt(0, 0, 0), gp_Pnt(4, 0, 0), 0.0),
                                                     arc(gp_Pnt(0, 3, 0), gp_Pnt(4, 3, 0), 0.0)};
  std::vector<Handle(Geom_BSplineCurve)> guides = {arc(gp_Pnt(0, 0, 0), gp_Pnt(0, 3, 0), 0.0),
                                                   arc(gp_Pnt(1, 0, 0), gp_Pnt(1, 3, 0), 0.5),
                                                   arc(gp_Pnt(4, 0, 0), gp_Pnt(4, 3, 0), 0.0)};
  const auto rows = roundedRows(profiles, guides);
  ASSERT_EQ(rows.size(), 1u);
  double u0, u1, v0, v1;
  rows[0]->Bounds(u0, u1, v0, v1);
  EXPECT_DOUBLE_EQ(u1, 2.0);
  for (double v : {0.0, 0.4, 1.0}) {
    EXPECT_LT(rows[0]->Value(1.0, v).Distance(guides[1]->Value(v)), 1e-12);  // the middle guide at u = 1
    EXPECT_LT(rows[0]->Value(2.0, v).Distance(guides[2]->Value(v)), 1e-12);
  }
  EXPECT_LT(rows[0]->Value(0.5, 0.0).Distance(gp_Pnt(0.5, 0, 0)), 1e-12);  // half of the first piece
  EXPECT_LT(rows[0]->Value(1.5, 1.0).Distance(gp_Pnt(2.5, 3, 0)), 1e-12);  // half of the second piece
}

TEST(CoonsPatchRows, EachCellKeepsItsOwnKnotsAlongTheRow) {
  // Profiles with knots at 0.1 and 0.6; guides meet them at 0, 0.25 and 1: the first cell's
  // pieces have a knot at 0.4 of their own parameter, the second's at 0.6 - 0.25 = 0.35 of
  // its 0.75, 0.4667. Side by side the row carries each where its cell has it: knots 0, 0.4,
  // 1, 1.4667, 2, not both in both cells.
  std::vector<Handle(Geom_BSplineCurve)> profiles = {arc(gp_Pnt(0, 0, 0), gp_Pnt(4, 0, 0), 0.3),
                                                     arc(gp_Pnt(0, 3, 0), gp_Pnt(4, 3, 0), 0.3)};
  for (auto& profile : profiles) {
    profile->InsertKnot(0.1);
    profile->InsertKnot(0.6);
  }
  std::vector<Handle(Geom_BSplineCurve)> guides = {arc(profiles[0]->Value(0.0), profiles[1]->Value(0.0), 0.0),
                                                   arc(profiles[0]->Value(0.25), profiles[1]->Value(0.25), 0.0),
                                                   arc(profiles[0]->Value(1.0), profiles[1]->Value(1.0), 0.0)};
  const auto rows = roundedRows(profiles, guides);
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0]->NbUKnots(), 5);
  EXPECT_NEAR(rows[0]->UKnot(2), 0.4, 1e-12);
  EXPECT_NEAR(rows[0]->UKnot(4), 1.0 + 0.35 / 0.75, 1e-12);
  for (double t : {0.05, 0.2, 0.4, 0.7, 0.95}) {  // the profile pieces, exactly
    const double u = t < 0.25 ? t / 0.25 : 1.0 + (t - 0.25) / 0.75;
    EXPECT_LT(rows[0]->Value(u, 0.0).Distance(profiles[0]->Value(t)), 1e-12);
    EXPECT_LT(rows[0]->Value(u, 1.0).Distance(profiles[1]->Value(t)), 1e-12);
  }
}

TEST(CoonsPatchRows, AnEmptyCellIsAnError) {
  // Two guides meeting the profiles at the same parameter leave an empty cell.
  std::vector<Handle(Geom_BSplineCurve)> profiles = {arc(gp_Pnt(0, 0, 0), gp_Pnt(4, 0, 0), 0.0),
                                                     arc(gp_Pnt(0, 3, 0), gp_Pnt(4, 3, 0), 0.0)};
  std::vector<Handle(Geom_BSplineCurve)> guides = {arc(gp_Pnt(0, 0, 0), gp_Pnt(0, 3, 0), 0.0),
                                                   arc(gp_Pnt(0, 0, 0), gp_Pnt(0, 3, 0), 0.0)};
  KnownCrossings crossings;
  crossings.profileParameters.resize(2, 2);
  crossings.profileParameters << 0.0, 0.0, 0.0, 0.0;
  crossings.guideParameters.resize(2, 2);
  crossings.guideParameters << 0.0, 0.0, 1.0, 1.0;
  EXPECT_THROW(buildCoonsPatchRows(profiles, guides, crossings,
                                   [](std::size_t, std::size_t) { return PatchBlending::Bilinear; }),
               Error);
}

}  // namespace
}  // namespace airshape::geometry
