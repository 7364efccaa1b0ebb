// Where a ruled shape meets a skin, traced along its rulings (or, where its faces are not
// ruled, along their curves in one direction): a wing-like body of two ruled faces (parabolic
// arcs along x, rulings along y) and two planar ends, its root inside a tube
// of radius 1 about the x axis (an exact rational B-spline cylinder). The crossing is the
// closed line (x, sqrt(1 - z(x)^2), z(x)) over both arcs, whose length is integrated here; a
// body whose rulings pass through the tube and one whose root the tube passes through are left
// to the Boolean section.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/traced_section.h"
#include "tube_skin.h"

namespace airshape::geometry {
namespace {

TopoDS_Shape tube(double radius) { return test::tubeSkin(radius); }

/// The ruled surface between the parabolic arc from (1, y, 0) over z = height at x = 2 to
/// (3, y, 0) at y = root and the same arc at y = tip: its rulings run along y.
Handle(Geom_BSplineSurface) ruledArc(double height, double root, double tip) {
  TColgp_Array2OfPnt poles(1, 3, 1, 2);
  for (int i = 1; i <= 3; ++i) {
    const double z = i == 2 ? 2.0 * height : 0.0;  // a quadratic Bézier peaks at half its middle pole
    poles(i, 1) = gp_Pnt(i, root, z);
    poles(i, 2) = gp_Pnt(i, tip, z);
  }
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0.0, knots(2) = 1.0;
  TColStd_Array1OfInteger uMultiplicities(1, 2), vMultiplicities(1, 2);
  uMultiplicities(1) = uMultiplicities(2) = 3;
  vMultiplicities(1) = vMultiplicities(2) = 2;
  return new Geom_BSplineSurface(poles, knots, knots, uMultiplicities, vMultiplicities, 2, 1);
}

/// The plane face between the two arcs' ends at parameter v.
TopoDS_Face endBetween(const Handle(Geom_BSplineSurface) & upper, const Handle(Geom_BSplineSurface) & lower, double v) {
  BRepBuilderAPI_MakeWire wire(BRepBuilderAPI_MakeEdge(upper->VIso(v)).Edge(),
                               BRepBuilderAPI_MakeEdge(lower->VIso(v)).Edge());
  return BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
}

/// The same surface of degree 2 along y: no longer ruled as a B-spline (three rows of poles),
/// it is traced along its curves in y instead, as a guided wing's faces are.
Handle(Geom_BSplineSurface) curvedArc(double height, double root, double tip) {
  Handle(Geom_BSplineSurface) surface = ruledArc(height, root, tip);
  surface->IncreaseDegree(2, 2);
  return surface;
}

/// A wing-like body: arcs of height ±0.2 between y = root and y = tip, and its planar ends.
TopoDS_Shape wingBody(double root, double tip, bool curved = false) {
  const auto arc = curved ? curvedArc : ruledArc;
  const Handle(Geom_BSplineSurface) upper = arc(0.2, root, tip), lower = arc(-0.2, root, tip);
  TopoDS_Compound body;
  BRep_Builder builder;
  builder.MakeCompound(body);
  builder.Add(body, BRepBuilderAPI_MakeFace(upper, 1e-9).Face());
  builder.Add(body, BRepBuilderAPI_MakeFace(lower, 1e-9).Face());
  builder.Add(body, endBetween(upper, lower, 0.0));
  builder.Add(body, endBetween(upper, lower, 1.0));
  return body;
}

/// The length of the closed line where the body of wingBody meets the unit tube, by Simpson's
/// rule over both arcs (z = 0.8 t (1 - t) on the upper one, x = 1 + 2 t).
double crossingLength() {
  const auto speed = [](double t) {
    const double z = 0.8 * t * (1 - t), dz = 0.8 * (1 - 2 * t);
    const double dy = -z * dz / std::sqrt(1 - z * z);
    return std::sqrt(4.0 + dy * dy + dz * dz);
  };
  constexpr int kSteps = 20000;
  double sum = speed(0.0) + speed(1.0);
  for (int i = 1; i < kSteps; ++i) sum += (i % 2 ? 4.0 : 2.0) * speed(static_cast<double>(i) / kSteps);
  return 2.0 * sum / (3.0 * kSteps);
}

double totalLength(const std::vector<TopoDS_Edge>& edges) {
  double length = 0.0;
  for (const TopoDS_Edge& edge : edges) length += lengthOf(edge);
  return length;
}

TEST(TracedSection, AWingFromInsideATubeMeetsItInOneClosedLineOfTheIntegratedLength) {
  const auto edges = tracedSection(wingBody(0.0, 3.0), tube(1.0), 1e-9);
  ASSERT_TRUE(edges.has_value());
  EXPECT_GE(edges->size(), 2u);
  EXPECT_NEAR(totalLength(*edges), crossingLength(), 1e-7);
}

TEST(TracedSection, AWingOfCurvedFacesIsTracedAlongItsCurves) {
  const auto edges = tracedSection(wingBody(0.0, 3.0, true), tube(1.0), 1e-9);
  ASSERT_TRUE(edges.has_value());
  EXPECT_NEAR(totalLength(*edges), crossingLength(), 1e-7);
  // Curves that pass through the tube meet it twice: left to the Boolean section.
  EXPECT_FALSE(tracedSection(wingBody(-3.0, 3.0, true), tube(1.0), 1e-9).has_value());
}

/// The bilinear patch through four corners: u from the first to the second, v to the third.
TopoDS_Face bilinear(const gp_Pnt& origin, const gp_Pnt& alongU, const gp_Pnt& alongV, const gp_Pnt& opposite) {
  return ruledFace(straightLine(origin, alongU), straightLine(alongV, opposite));
}

TEST(TracedSection, FacesRuledAlongTheirCrossingAreTracedTheOtherWay) {
  // A flat bar from x = 1 to 2, z = ±0.05, along y from 0 (inside the unit tube) to 3. Each
  // face's rulings run across the bar, nearly along where it meets the tube: the curves along
  // y find the crossing instead. It is two arcs of the unit circle over z = ±0.05 at x = 1 and
  // 2, and two lines of length 1 along x.
  const double h = 0.05;
  BRep_Builder builder;
  TopoDS_Compound bar;
  builder.MakeCompound(bar);
  for (const double x : {1.0, 2.0}) builder.Add(bar, bilinear({x, 0, -h}, {x, 3, -h}, {x, 0, h}, {x, 3, h}));
  for (const double z : {-h, h}) builder.Add(bar, bilinear({1, 0, z}, {1, 3, z}, {2, 0, z}, {2, 3, z}));
  for (const double y : {0.0, 3.0}) {
    BRepBuilderAPI_MakePolygon end(gp_Pnt(1, y, -h), gp_Pnt(2, y, -h), gp_Pnt(2, y, h), gp_Pnt(1, y, h), true);
    builder.Add(bar, BRepBuilderAPI_MakeFace(end.Wire(), true).Face());
  }
  const auto edges = tracedSection(bar, tube(1.0), 1e-9);
  ASSERT_TRUE(edges.has_value());
  EXPECT_NEAR(totalLength(*edges), 2.0 + 4.0 * std::asin(h), 1e-7);
}

TEST(TracedSection, AWingThatMissesTheTubeMeetsItNowhere) {
  const auto edges = tracedSection(wingBody(1.5, 3.0), tube(1.0), 1e-9);
  ASSERT_TRUE(edges.has_value());
  EXPECT_TRUE(edges->empty());
}

TEST(TracedSection, RulingsThatPassThroughTheTubeAreLeftToTheBooleanSection) {
  // Each ruling from y = -3 to 3 meets the tube twice.
  EXPECT_FALSE(tracedSection(wingBody(-3.0, 3.0), tube(1.0), 1e-9).has_value());
}

TEST(TracedSection, ARootThatTheTubePassesThroughIsLeftToTheBooleanSection) {
  // A tube of radius 0.1 runs through the wing's root face, which tracing does not cover.
  EXPECT_FALSE(tracedSection(wingBody(0.0, 3.0), tube(0.1), 1e-9).has_value());
}

}  // namespace
}  // namespace airshape::geometry
