// Where the lines of a ruled surface meet a skin (ruled_crossing.h) when they meet it twice: far
// off, as a box wing's other wing, the meeting nearest the lines' bases counts; close by, the
// skin folds back over itself and the crossing is left to the Boolean operation.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomConvert.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <cmath>

#include "airshape/geometry/bspline_patch.h"
#include "airshape/geometry/ruled_crossing.h"
#include "test_wing_skins.h"

namespace airshape::geometry {
namespace {

/// The small wing's upper skin and a copy of it lifted by `lift` along z, as one skin.
std::vector<Patch> skinWithCopyAbove(double lift) {
  return skinPatches(test::upperSkinWithCopy(gp_Vec(0, 0, lift)))->patches;
}

// Lines up along z from the chord plane at x = 0.5, from y = 0.2 to 0.8.
const RuledLines kUpFromChord{gp_Pnt(0.5, 0.2, 0.0), gp_Pnt(0.5, 0.8, 0.0), gp_Vec(0, 0, 1), gp_Vec(0, 0, 1)};

TEST(RuledCrossing, TakesTheNearSkinWhereTheLinesMeetAnotherFarOff) {
  const auto pieces = ruledCrossing(skinWithCopyAbove(3.0), kUpFromChord, 1e-9);
  ASSERT_TRUE(pieces.has_value());
  ASSERT_EQ(pieces->size(), 1u);
  EXPECT_EQ(pieces->front().patch, 0u);  // the skin as it is, not the lifted copy
  for (const PatchPoint& point : pieces->front().points) EXPECT_LT(point.point.Z(), 0.1);
  EXPECT_NEAR(pieces->front().points.front().point.Y(), 0.2, 1e-9);
  EXPECT_NEAR(pieces->front().points.back().point.Y(), 0.8, 1e-9);
}

TEST(RuledCrossing, RefusesASkinThatFoldsBackCloseBy) {
  EXPECT_THROW(ruledCrossing(skinWithCopyAbove(0.2), kUpFromChord, 1e-9), FoldedSkin);
}

TEST(RuledCrossing, FollowsTheSkinToWhereALineTouchesItsLeadingEdge) {
  // Lines up along z from x = 0.3 to x = 0 at mid span: the last touches the skin at its leading
  // edge, where the skin stands upright, so the crossing goes there like a square root of t.
  const RuledLines toTheNose{gp_Pnt(0.3, 0.5, -1.0), gp_Pnt(0.0, 0.5, -1.0), gp_Vec(0, 0, 1), gp_Vec(0, 0, 1)};
  const std::vector<Patch> patches = skinPatches(test::upperSkin())->patches;
  const auto pieces = ruledCrossing(patches, toTheNose, 1e-9);
  ASSERT_TRUE(pieces.has_value());
  ASSERT_EQ(pieces->size(), 1u);
  const CrossingPiece& piece = pieces->front();
  EXPECT_NEAR(piece.points.back().point.Distance(gp_Pnt(0.0, 0.5, 0.0)), 0.0, 1e-9);
  // The curve follows the crossing between its points, close to the nose too.
  const Patch& patch = patches.front();
  for (double t : {0.5, 0.9, 0.99, 0.999, 0.99999}) {
    const gp_Pnt2d uv = piece.curve->Value(t);
    const gp_Pnt onCurve = patch.surface->Value(uv.X(), uv.Y());
    EXPECT_NEAR(onCurve.X(), 0.3 * (1.0 - t), 1e-8) << "at t = " << t;
    EXPECT_NEAR(onCurve.Y(), 0.5, 1e-8) << "at t = " << t;
  }
}

TEST(RuledCrossing, LeavesOutLinesThatMeetTheSkinOnlyAtItsCorner) {
  // Lines up along z from the trailing edge's root corner (x = 1, y = 0) outwards and aft: the
  // first meets the skin at that corner, all others pass beyond its trailing edge and its root.
  // The lines within the tolerance of the corner meet it there, a crossing that draws no curve.
  const RuledLines pastTheCorner{gp_Pnt(1.0, 0.0, -1.0), gp_Pnt(1.5, -0.5, -1.0), gp_Vec(0, 0, 1), gp_Vec(0, 0, 1)};
  const auto pieces = ruledCrossing(skinPatches(test::upperSkin())->patches, pastTheCorner, 1e-8);
  ASSERT_TRUE(pieces.has_value());
  EXPECT_TRUE(pieces->empty());
}

TEST(RuledCrossing, CoversAllLinesFromTheSeamOfASkinAllRound) {
  // A skin all round (one face of a cylinder about z, its seam at x > 0) and rays from its axis
  // turning from the seam the way its parameter runs back: as a frame's rays start on the seam
  // of a fuselage's face. The first ray meets the skin at the seam's start and its end alike;
  // the crossing must still cover every ray, the first too.
  const Handle(Geom_Surface) cylinder = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 2.0);
  const Handle(Geom_BSplineSurface) round =
      GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(cylinder, 0.0, 2.0 * M_PI, 0.0, 1.0));
  const TopoDS_Face skin = BRepBuilderAPI_MakeFace(round, 1e-9).Face();
  const RuledLines backFromTheSeam{gp_Pnt(0, 0, 0.5), gp_Pnt(0, 0, 0.5), gp_Vec(1, 0, 0), gp_Vec(0, -1, 0), true};
  const auto pieces = ruledCrossing(skinPatches(skin)->patches, backFromTheSeam, 1e-9);
  ASSERT_TRUE(pieces.has_value());
  ASSERT_FALSE(pieces->empty());
  EXPECT_TRUE(coversAllLines(*pieces));
  EXPECT_NEAR(pieces->front().points.front().point.Distance(gp_Pnt(2, 0, 0.5)), 0.0, 1e-7);
  EXPECT_NEAR(pieces->back().points.back().point.Distance(gp_Pnt(0, -2, 0.5)), 0.0, 1e-7);
}

TEST(RuledCrossing, CoversAllLinesFromTheFirstToTheLastWithoutGapsBeyondRounding) {
  auto piece = [](double from, double to) {
    CrossingPiece made{0, {}, nullptr};
    made.points.resize(2);
    made.points[0].t = from;
    made.points[1].t = to;
    return made;
  };
  EXPECT_TRUE(coversAllLines({piece(0.0, 0.5), piece(0.5, 1.0)}));
  EXPECT_TRUE(coversAllLines({piece(0.0, 0.5), piece(0.5 + 5e-10, 1.0)}));
  EXPECT_FALSE(coversAllLines({piece(0.0, 0.4), piece(0.5, 1.0)}));
  EXPECT_FALSE(coversAllLines({piece(1e-9, 1.0)}));
  EXPECT_FALSE(coversAllLines({piece(0.0, 0.999)}));
  EXPECT_FALSE(coversAllLines({}));
}

}  // namespace
}  // namespace airshape::geometry
