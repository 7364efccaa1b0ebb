// A section straight from two skins whose blunt trailing edge is twisted (skin_section.h): it is
// closed by the exact curve where the plane meets the ruled face between the skins' last lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include "airshape/geometry/skin_section.h"
#include "test_area.h"
#include "test_wing_skins.h"

namespace airshape::geometry {
namespace {

using test::kLowerRoot;
using test::kLowerTip;
using test::kUpperRoot;
using test::kUpperTip;
using test::lowerSkin;
using test::upperSkin;

/// How far a point lies from the ruled face between the trailing-edge lines: from the nearest
/// of its rulings, joining the lines' points of equal share.
double offTrailingEdgeFace(const gp_Pnt& point) {
  double nearest = std::numeric_limits<double>::max();
  const auto off = [&](double share) {
    const gp_Pnt a(kUpperRoot.XYZ() + share * (kUpperTip.XYZ() - kUpperRoot.XYZ()));
    const gp_Pnt b(kLowerRoot.XYZ() + share * (kLowerTip.XYZ() - kLowerRoot.XYZ()));
    const gp_Vec ruling(a, b);
    return gp_Vec(a, point).Crossed(ruling.Normalized()).Magnitude();
  };
  double low = 0.0, high = 1.0;
  for (int round = 0; round < 16; ++round) {  // narrowing a sampled bracket
    double best = low;
    for (int i = 0; i <= 20; ++i) {
      const double share = low + (high - low) * i / 20.0;
      if (off(share) < off(best)) best = share;
    }
    const double step = (high - low) / 20.0;
    low = std::max(0.0, best - step), high = std::min(1.0, best + step);
    nearest = off(best);
  }
  return nearest;
}

// An oblique plane across the span, its lines running from the lower skin to the upper.
const gp_Vec kNormal = gp_Vec(0.2, 1.0, 0.1).Normalized();
const CrossingLines kLines{gp_Pnt(0.0, 0.5, 0.0), gp_Vec(1.0, -0.2, 0.0),
                           kNormal.Crossed(gp_Vec(1.0, -0.2, 0.0)).Normalized()};

/// The section of the two skins in that plane, open at both ends.
std::optional<TopoDS_Face> twistedSection(OpenEnds openEnds) {
  const TopoDS_Face upper = upperSkin(), lower = lowerSkin();
  return sectionBetweenSkins(upper, lower, kLines, CrossingEnd::open(), CrossingEnd::open(), 1e-9, openEnds);
}

TEST(BluntEdgeSection, TwistedTrailingEdgeIsClosedOnItsRuledFace) {
  const auto face = twistedSection(OpenEnds::SkinsMeet);
  ASSERT_TRUE(face);
  int closing = 0;
  for (TopExp_Explorer explorer(*face, TopAbs_EDGE); explorer.More(); explorer.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(explorer.Current());
    if (BRep_Tool::Pnt(TopExp::FirstVertex(edge)).X() < 0.9 || BRep_Tool::Pnt(TopExp::LastVertex(edge)).X() < 0.9)
      continue;
    ++closing;
    const BRepAdaptor_Curve curve(edge);
    for (int i = 0; i <= 10; ++i) {
      const gp_Pnt point =
          curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / 10);
      EXPECT_LT(offTrailingEdgeFace(point), 1e-12);
      EXPECT_LT(std::abs(gp_Vec(kLines.origin, point).Dot(kNormal)), 1e-12);
    }
  }
  EXPECT_EQ(closing, 1);
  EXPECT_GT(test::accurateArea(*face), 0.0);
}

TEST(BluntEdgeSection, ClosedStraightWhenAskedTo) {
  const auto twisted = twistedSection(OpenEnds::SkinsMeet), straight = twistedSection(OpenEnds::ClosedStraight);
  ASSERT_TRUE(twisted);
  ASSERT_TRUE(straight);
  // The twisted face bulges beyond the chord between the skins' ends, by a little.
  EXPECT_GT(std::abs(test::accurateArea(*twisted) - test::accurateArea(*straight)), 1e-9);
  EXPECT_LT(std::abs(test::accurateArea(*twisted) - test::accurateArea(*straight)),
            1e-3 * test::accurateArea(*twisted));
}

}  // namespace
}  // namespace airshape::geometry
