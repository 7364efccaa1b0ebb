// A section straight from two skins whose blunt trailing edge is twisted (skin_section.h): it is
// closed by the exact curve where the plane meets the ruled face between the skins' last lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include "skin_section.h"

namespace airshape::structure {
namespace {

// The trailing-edge lines of the skins, from the root (y = 0) to the tip (y = 1): skew.
const gp_Pnt kUpperRoot(1, 0, 0.01), kUpperTip(1, 1, 0.03);
const gp_Pnt kLowerRoot(1, 0, -0.01), kLowerTip(1.05, 1, 0.0);

/// A skin from the leading edge (the origin's line along y) to a trailing-edge line, cubic
/// along the chord through a crest, straight along the span.
TopoDS_Face skin(double crest, const gp_Pnt& root, const gp_Pnt& tip) {
  const auto chord = [&](double y, const gp_Pnt& end) {
    return std::vector<gp_Pnt>{gp_Pnt(0, y, 0), gp_Pnt(0, y, 0.6 * crest), gp_Pnt(0.5, y, crest), end};
  };
  const std::vector<gp_Pnt> atRoot = chord(0.0, root), atTip = chord(1.0, tip);
  TColgp_Array2OfPnt poles(1, static_cast<int>(atRoot.size()), 1, 2);
  for (std::size_t i = 0; i < atRoot.size(); ++i) {
    poles.SetValue(static_cast<int>(i) + 1, 1, atRoot[i]);
    poles.SetValue(static_cast<int>(i) + 1, 2, atTip[i]);
  }
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  TColStd_Array1OfInteger uMultiplicities(1, 2), vMultiplicities(1, 2);
  uMultiplicities.Init(4);
  vMultiplicities.Init(2);
  const Handle(Geom_BSplineSurface) surface =
      new Geom_BSplineSurface(poles, knots, knots, uMultiplicities, vMultiplicities, 3, 1);
  return BRepBuilderAPI_MakeFace(surface, 1e-9).Face();
}

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
  const TopoDS_Face upper = skin(0.08, kUpperRoot, kUpperTip), lower = skin(-0.06, kLowerRoot, kLowerTip);
  return sectionBetweenSkins(upper, lower, kLines, CrossingEnd::open(), CrossingEnd::open(), 1e-9, openEnds);
}

double areaOf(const TopoDS_Face& face) {
  GProp_GProps properties;
  BRepGProp::SurfaceProperties(face, properties, 1e-12);
  return properties.Mass();
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
  EXPECT_GT(areaOf(*face), 0.0);
}

TEST(BluntEdgeSection, ClosedStraightWhenAskedTo) {
  const auto twisted = twistedSection(OpenEnds::SkinsMeet), straight = twistedSection(OpenEnds::ClosedStraight);
  ASSERT_TRUE(twisted);
  ASSERT_TRUE(straight);
  // The twisted face bulges beyond the chord between the skins' ends, by a little.
  EXPECT_GT(std::abs(areaOf(*twisted) - areaOf(*straight)), 1e-9);
  EXPECT_LT(std::abs(areaOf(*twisted) - areaOf(*straight)), 1e-3 * areaOf(*twisted));
}

}  // namespace
}  // namespace airshape::structure
