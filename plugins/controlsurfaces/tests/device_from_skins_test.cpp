// A device made from its wing's skins without a Boolean operation (device_from_skins.h), on a
// wing whose volumes are known in closed form: a rectangular wing of unit chord along x and
// unit span along y, its skins the parabolas z = 4 c x (1 - x) above and z = -4 c x (1 - x)
// below (exact quadratic B-splines), sharp at both edges.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/ruled_sections.h"
#include "device_from_skins.h"

namespace airshape::controlsurfaces {
namespace {

constexpr double kUpperCrest = 0.06, kLowerCrest = 0.04;  // c of the upper and the lower skin
constexpr double kInnerY = 0.2, kOuterY = 0.8;            // the devices' borders
constexpr double kTolerance = 1e-9;

/// A skin z = sign 4 c x (1 - x) over the unit square: a quadratic along x, straight along y.
TopoDS_Face skin(double crest) {
  const auto chord = [crest](double y) {
    TColgp_Array1OfPnt poles(1, 3);
    poles.SetValue(1, gp_Pnt(0.0, y, 0.0));
    poles.SetValue(2, gp_Pnt(0.5, y, 2.0 * crest));
    poles.SetValue(3, gp_Pnt(1.0, y, 0.0));
    TColStd_Array1OfReal knots(1, 2);
    knots.SetValue(1, 0.0);
    knots.SetValue(2, 1.0);
    TColStd_Array1OfInteger multiplicities(1, 2);
    multiplicities.Init(3);
    return Handle(Geom_BSplineCurve)(new Geom_BSplineCurve(poles, knots, multiplicities, 2));
  };
  return BRepBuilderAPI_MakeFace(geometry::ruledSurface(chord(0.0), chord(1.0)), 1e-12).Face();
}

WingSkins wingSkins() { return {skin(kUpperCrest), skin(-kLowerCrest), {}}; }

/// The integral of 4 x (1 - x) from a to b: a skin's height over its crest, summed.
double underParabola(double a, double b) {
  const auto primitive = [](double x) { return 2.0 * x * x - 4.0 * x * x * x / 3.0; };
  return primitive(b) - primitive(a);
}

/// An outline in the border plane y: its corners (x, z) in order.
TopoDS_Wire outline(double y, const std::vector<std::pair<double, double>>& corners) {
  BRepBuilderAPI_MakePolygon polygon;
  for (const auto& [x, z] : corners) polygon.Add(gp_Pnt(x, y, z));
  polygon.Close();
  return polygon.Wire();
}

/// A straight cut across the wing at x, from below the wing to above it, closed far aft
/// (`reach` > 0) or far ahead (< 0), as borderOutline and closedOutlines draw it.
TopoDS_Wire cutAt(double y, double x, double reach) {
  return outline(y, {{x, -0.5}, {x, 0.5}, {x + reach, 0.5}, {x + reach, -0.5}});
}

DeviceFaceNames names(const std::string& cutterFaces) { return {"D/", cutterFaces}; }

bool hasFaceNamed(const NamedShape& shape, const std::string& name) {
  for (const auto& face : shape.faces)
    if (face.first == name) return true;
  return false;
}

TEST(DeviceFromSkins, AFlapAftOfAStraightCutIsTheWingAftOfIt) {
  const auto flap = deviceFromSkins(wingSkins(), OutlineKind::Aft, cutAt(kInnerY, 0.7, 5.0), cutAt(kOuterY, 0.7, 5.0),
                                    {}, {}, names("leading edge"), kTolerance);
  ASSERT_TRUE(flap.has_value()) << "made directly, not left to the Boolean operation";
  EXPECT_TRUE(BRepCheck_Analyzer(flap->shape).IsValid());
  const double section = (kUpperCrest + kLowerCrest) * underParabola(0.7, 1.0);
  EXPECT_NEAR(geometry::enclosedVolume(flap->shape), (kOuterY - kInnerY) * section, 1e-10);
  for (const char* part : {"upper", "lower", "leading edge", "inner side", "outer side"})
    EXPECT_TRUE(hasFaceNamed(*flap, std::string("D/") + part)) << part;
}

TEST(DeviceFromSkins, ACutAtTheLeadingEdgeTakesTheWholeChord) {
  // An all-moving surface: the cut touches the skins only where they meet, at x = 0.
  const auto whole = deviceFromSkins(wingSkins(), OutlineKind::WholeChord, cutAt(kInnerY, 0.0, 5.0),
                                     cutAt(kOuterY, 0.0, 5.0), {}, {}, names("leading edge"), kTolerance);
  ASSERT_TRUE(whole.has_value()) << "made directly, not left to the Boolean operation";
  EXPECT_TRUE(BRepCheck_Analyzer(whole->shape).IsValid());
  const double section = (kUpperCrest + kLowerCrest) * underParabola(0.0, 1.0);
  EXPECT_NEAR(geometry::enclosedVolume(whole->shape), (kOuterY - kInnerY) * section, 1e-10);
  EXPECT_FALSE(hasFaceNamed(*whole, "D/leading edge")) << "no front: the skins meet there";
  for (const char* part : {"upper", "lower", "inner side", "outer side"})
    EXPECT_TRUE(hasFaceNamed(*whole, std::string("D/") + part)) << part;
}

TEST(DeviceFromSkins, ASlatAheadOfAStraightCutIsTheNose) {
  const TopoDS_Wire inner = cutAt(kInnerY, 0.15, -5.0), outer = cutAt(kOuterY, 0.15, -5.0);
  const TopoDS_Shape cutter = geometry::ruledThroughSections({outer, inner}).solid;
  const auto slat =
      deviceFromSkins(wingSkins(), OutlineKind::Ahead, inner, outer, cutter, {}, names("trailing edge"), kTolerance);
  ASSERT_TRUE(slat.has_value());
  EXPECT_TRUE(BRepCheck_Analyzer(slat->shape).IsValid());
  const double section = (kUpperCrest + kLowerCrest) * underParabola(0.0, 0.15);
  EXPECT_NEAR(geometry::enclosedVolume(slat->shape), (kOuterY - kInnerY) * section, 1e-10);
}

TEST(DeviceFromSkins, ASpoilerIsTheUpperSkinAboveItsPanel) {
  // The panel's underside runs straight from (0.4, 0) to (0.6, 0), the chord line.
  const auto panel = [](double y) { return outline(y, {{0.4, 0.0}, {0.4, 0.5}, {0.6, 0.5}, {0.6, 0.0}}); };
  const auto spoiler = deviceFromSkins(wingSkins(), OutlineKind::Panel, panel(kInnerY), panel(kOuterY), {}, {},
                                       names("lower"), kTolerance);
  ASSERT_TRUE(spoiler.has_value());
  EXPECT_TRUE(BRepCheck_Analyzer(spoiler->shape).IsValid());
  EXPECT_NEAR(geometry::enclosedVolume(spoiler->shape), (kOuterY - kInnerY) * kUpperCrest * underParabola(0.4, 0.6),
              1e-10);
  EXPECT_TRUE(hasFaceNamed(*spoiler, "D/upper") && hasFaceNamed(*spoiler, "D/lower"));
}

/// A rounded nose at x in the border plane y: a parabola from the lower skin forward through
/// (x - depth, 0) to the upper skin, then straight edges up, far aft, down and forward back to
/// the lower skin, as borderOutline draws a flap's leading-edge shape.
TopoDS_Wire roundedNoseAt(double y, double x, double depth) {
  const double upper = 4.0 * kUpperCrest * x * (1.0 - x), lower = -4.0 * kLowerCrest * x * (1.0 - x);
  TColgp_Array1OfPnt poles(1, 3);
  poles.SetValue(1, gp_Pnt(x, y, lower));
  poles.SetValue(2, gp_Pnt(x - depth, y, 0.0));
  poles.SetValue(3, gp_Pnt(x, y, upper));
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(3);
  BRepBuilderAPI_MakeWire wire(BRepBuilderAPI_MakeEdge(new Geom_BSplineCurve(poles, knots, multiplicities, 2)).Edge());
  BRepBuilderAPI_MakePolygon rest;
  for (const auto& [px, pz] : std::vector<std::pair<double, double>>{
           {x, upper}, {x, 0.5}, {x + 5.0, 0.5}, {x + 5.0, -0.5}, {x, -0.5}, {x, lower}})
    rest.Add(gp_Pnt(px, y, pz));
  wire.Add(rest.Wire());
  return wire.Wire();
}

TEST(DeviceFromSkins, AFlapWithARoundedNoseHoldsTheNose) {
  const TopoDS_Wire inner = roundedNoseAt(kInnerY, 0.7, 0.05), outer = roundedNoseAt(kOuterY, 0.7, 0.05);
  const TopoDS_Shape cutter = geometry::ruledThroughSections({outer, inner}).solid;
  const TopoDS_Face nose = geometry::ruledFaceBetween(TopoDS::Edge(TopExp_Explorer(inner, TopAbs_EDGE).Current()),
                                                      TopoDS::Edge(TopExp_Explorer(outer, TopAbs_EDGE).Current()));
  const auto flap =
      deviceFromSkins(wingSkins(), OutlineKind::Aft, inner, outer, cutter, nose, names("leading edge"), kTolerance);
  ASSERT_TRUE(flap.has_value());
  EXPECT_TRUE(BRepCheck_Analyzer(flap->shape).IsValid());
  // The parabola's bulge ahead of the cut holds two thirds of its triangle: height times depth / 3.
  const double height = 4.0 * (kUpperCrest + kLowerCrest) * 0.7 * 0.3;
  const double section = (kUpperCrest + kLowerCrest) * underParabola(0.7, 1.0) + height * 0.05 / 3.0;
  EXPECT_NEAR(geometry::enclosedVolume(flap->shape), (kOuterY - kInnerY) * section, 1e-10);
}

TEST(DeviceFromSkins, ACutThatMissesTheWingIsLeftToTheBooleanOperation) {
  // Beyond the trailing edge the cut's lines meet no skin.
  EXPECT_FALSE(deviceFromSkins(wingSkins(), OutlineKind::Aft, cutAt(kInnerY, 1.5, 5.0), cutAt(kOuterY, 1.5, 5.0), {},
                               {}, names("leading edge"), kTolerance)
                   .has_value());
}

}  // namespace
}  // namespace airshape::controlsurfaces
