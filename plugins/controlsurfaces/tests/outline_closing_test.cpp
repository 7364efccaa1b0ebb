// A device's outlines closed outside the wing (outline_closing.h): both borders' far edges in
// three common planes, the edges that leave the wing untouched, and the cases closed alone.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/geometry/ruled_sections.h"
#include "outline_closing.h"

namespace airshape::controlsurfaces {
namespace {

/// The corners of a wire in the order it runs.
std::vector<gp_Pnt> cornersOf(const TopoDS_Wire& wire) {
  std::vector<gp_Pnt> corners;
  for (BRepTools_WireExplorer edge(wire); edge.More(); edge.Next())
    corners.push_back(BRep_Tool::Pnt(edge.CurrentVertex()));
  return corners;
}

/// Whether four points lie in one plane, to a length.
bool coplanar(const gp_Pnt& a, const gp_Pnt& b, const gp_Pnt& c, const gp_Pnt& d, double tolerance) {
  const gp_Vec normal = gp_Vec(a, b).Crossed(gp_Vec(a, c));
  return std::abs(gp_Vec(a, d).Dot(normal.Normalized())) < tolerance;
}

/// A straight cut across a wing section in `plane` at 0.3 of its chord, from the lower skin at
/// height -`thickness` / 2 to the upper one, aft of it the device, closed alone 5 chords along
/// and 5 half-thicknesses above and below.
BorderOutline cutIn(const BorderPlane& plane, double thickness) {
  BorderOutline outline(BorderOutline::Kind::Across, plane);
  outline.lower = gp_Pnt2d(0.3 * plane.chord, -0.5 * thickness);
  outline.upper = gp_Pnt2d(0.3 * plane.chord, 0.5 * thickness);
  outline.upOut = gp_Vec2d(0.0, 1.0);
  outline.downOut = gp_Vec2d(0.0, -1.0);
  outline.reach = 5.0;
  outline.height = 5.0 * 0.5 * thickness;
  return outline;
}

/// The same in the plane y = `y`, its chord `chord` along x from x = `front`.
BorderOutline cutAcross(double y, double front, double chord, double thickness) {
  return cutIn(BorderPlane(gp_Pnt(front, y, 0.0), gp_Pnt(front + chord, y, 0.0), gp_Vec(0, 0, 1)), thickness);
}

TEST(OutlineClosing, FarEdgesOfTwoBordersLieInCommonPlanes) {
  // A tapered, swept device: its borders differ in chord, thickness and place.
  const std::vector<TopoDS_Wire> wires =
      closedOutlines({cutAcross(0.0, 0.0, 2.0, 0.2), cutAcross(3.0, 1.0, 1.0, 0.08)});
  ASSERT_EQ(wires.size(), 2u);
  const std::vector<gp_Pnt> inner = cornersOf(wires[0]), outer = cornersOf(wires[1]);
  ASSERT_EQ(inner.size(), 4u);
  ASSERT_EQ(outer.size(), 4u);
  // Corners: lower out, upper out, upper far, lower far. The cut's ends stay where each
  // border reaches them alone (5 half-thicknesses above and below its chord).
  EXPECT_NEAR(inner[1].Z(), 0.5, 1e-12);
  EXPECT_NEAR(outer[1].Z(), 0.2, 1e-12);
  EXPECT_NEAR(inner[0].Z(), -0.5, 1e-12);
  EXPECT_NEAR(inner[1].X(), 0.6, 1e-12);
  // Lid, far side and bottom are plane.
  EXPECT_TRUE(coplanar(inner[1], inner[2], outer[2], outer[1], 1e-12));
  EXPECT_TRUE(coplanar(inner[2], inner[3], outer[3], outer[2], 1e-12));
  EXPECT_TRUE(coplanar(inner[3], inner[0], outer[0], outer[3], 1e-12));
  // Each wire stays in its border plane and reaches beyond both trailing edges.
  for (const gp_Pnt& p : inner) EXPECT_NEAR(p.Y(), 0.0, 1e-12);
  for (const gp_Pnt& p : outer) EXPECT_NEAR(p.Y(), 3.0, 1e-12);
  EXPECT_GT(inner[2].X(), 2.5);
  EXPECT_GT(outer[2].X(), 2.5);

  // The ruled solid between them has those three sides as planes.
  const geometry::RuledSections loft = geometry::ruledThroughSections(wires);
  ASSERT_FALSE(loft.solid.IsNull());
  int planes = 0;
  for (TopExp_Explorer face(loft.solid, TopAbs_FACE); face.More(); face.Next())
    if (BRepAdaptor_Surface(TopoDS::Face(face.Current())).GetType() == GeomAbs_Plane) ++planes;
  EXPECT_EQ(planes, 6);  // the two borders, lid, far side, bottom, and the cut (vertical at both borders)
}

TEST(OutlineClosing, BorderPlanesMeetingInsideTheCommonReachCloseNearerOrAlone) {
  // A large inner border (chord 4) and a small outer one (chord 0.5) whose plane is turned
  // towards it: common far corners 2 past the trailing edges (the small border's own margin)
  // would lie beyond the line where the planes meet.
  const BorderOutline inner = cutAcross(0.0, 0.0, 4.0, 0.4);
  const gp_Pnt outerFront(3.5, 1.0, 0.0);
  const auto outerTurnedBy = [&](double turn) {
    const BorderPlane turned(outerFront, outerFront.Translated(0.5 * gp_Vec(std::cos(turn), -std::sin(turn), 0.0)),
                             gp_Vec(0, 0, 1));
    return cutIn(turned, 0.4);  // as thick as the inner border, so the lid is level
  };
  // Turned 0.4 rad, the planes meet at x = 3.5 + cot 0.4 = 5.87: the far plane is brought
  // nearer (half the margin, x = 5), still past both trailing edges.
  const std::vector<gp_Pnt> nearer = cornersOf(closedOutlines({inner, outerTurnedBy(0.4)})[0]);
  ASSERT_EQ(nearer.size(), 4u);
  EXPECT_NEAR(nearer[2].X(), 5.0, 1e-9);

  // Turned 0.96 rad, they meet at 4.21, before an eighth of the margin (4.25): closed alone, the
  // far corners 5 chords along each border's own chord.
  const std::vector<gp_Pnt> alone = cornersOf(closedOutlines({inner, outerTurnedBy(0.96)})[0]);
  ASSERT_EQ(alone.size(), 4u);
  EXPECT_NEAR(alone[2].X(), 20.0, 1e-12);
  EXPECT_NEAR(alone[2].Z(), 1.0, 1e-12);

  // Turned 0.3 rad (meeting at 6.74), the common far corners at the whole margin (6.0) are used.
  const std::vector<gp_Pnt> common = cornersOf(closedOutlines({inner, outerTurnedBy(0.3)})[0]);
  ASSERT_EQ(common.size(), 4u);
  EXPECT_NEAR(common[2].X(), 6.0, 1e-9);
}

/// The plane of a panel's border at y = `y`: its chord along x from x = 0, twisted along y.
BorderPlane panelPlane(double y) { return BorderPlane(gp_Pnt(0.0, y, 0.0), gp_Pnt(1.0, y, -0.1 * y), gp_Vec(0, 0, 1)); }

/// A spoiler's panel in `plane`: its lower side at height `depth` from x = `front` to `back`,
/// closed above the wing at `height`.
BorderOutline panelIn(const BorderPlane& plane, double front, double back, double depth, double height) {
  BorderOutline panel(BorderOutline::Kind::Panel, plane);
  panel.upper = gp_Pnt2d(front, depth);
  panel.lower = gp_Pnt2d(back, depth);
  panel.upOut = panel.downOut = gp_Vec2d(0.0, 1.0);
  panel.height = height;
  return panel;
}

TEST(OutlineClosing, PanelsAndAirfoilsCloseAlone) {
  const BorderPlane plane = panelPlane(0.0);
  const BorderOutline panel = panelIn(plane, 0.2, 0.6, 0.02, 0.3);  // front, back
  BorderOutline airfoil(BorderOutline::Kind::Airfoil, plane);
  airfoil.airfoil = BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0.01), gp_Pnt(1, 0, -0.01), true).Wire();
  const std::vector<TopoDS_Wire> wires = closedOutlines({panel, airfoil});
  ASSERT_EQ(wires.size(), 2u);
  const std::vector<gp_Pnt> corners = cornersOf(wires[0]);
  ASSERT_EQ(corners.size(), 4u);  // front, above it, above the back, back
  EXPECT_NEAR(corners[1].Z(), 0.3, 1e-12);
  EXPECT_NEAR(corners[2].Z(), 0.3, 1e-12);
  EXPECT_TRUE(wires[1].IsSame(airfoil.airfoil));
}

TEST(OutlineClosing, TwoPanelsShareTheirLidsPlane) {
  // Panels of different depth and height, their planes' upward directions apart.
  const std::vector<TopoDS_Wire> wires =
      closedOutlines({panelIn(panelPlane(0.0), 0.2, 0.6, 0.02, 0.3), panelIn(panelPlane(2.0), 0.3, 0.6, 0.01, 0.2)});
  ASSERT_EQ(wires.size(), 2u);
  const std::vector<gp_Pnt> inner = cornersOf(wires[0]), outer = cornersOf(wires[1]);
  ASSERT_EQ(inner.size(), 4u);
  ASSERT_EQ(outer.size(), 4u);
  // Corners: front, above it, above the back, back. Three corners above as each panel alone.
  EXPECT_NEAR(inner[1].Z(), 0.3, 1e-12);
  EXPECT_NEAR(inner[2].Z(), 0.3, 1e-12);
  EXPECT_TRUE(coplanar(inner[1], inner[2], outer[2], outer[1], 1e-12));
  // The outer back's edge still leaves along its plane's upward direction.
  const gp_Vec up = gp_Vec(outer[3], outer[2]).Normalized();
  EXPECT_NEAR(up.Dot(panelPlane(2.0).y), 1.0, 1e-12);
  // Alone, the four corners above would not lie in one plane.
  EXPECT_FALSE(coplanar(inner[1], inner[2], panelPlane(2.0).at(0.3, 0.2), panelPlane(2.0).at(0.6, 0.2), 1e-6));
}

}  // namespace
}  // namespace airshape::controlsurfaces
