#pragma once
// Two skins of a small wing for the plugin's tests: cubic along the chord from a common leading
// edge (the y axis) to blunt trailing-edge lines, straight along the span from y = 0 to 1.

#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

namespace airshape::test {

// The trailing-edge lines of the skins, from the root (y = 0) to the tip (y = 1): skew.
inline const gp_Pnt kUpperRoot(1, 0, 0.01), kUpperTip(1, 1, 0.03);
inline const gp_Pnt kLowerRoot(1, 0, -0.01), kLowerTip(1.05, 1, 0.0);

/// A skin from the leading edge (the origin's line along y) to a trailing-edge line, cubic
/// along the chord through a crest, straight along the span.
inline TopoDS_Face skin(double crest, const gp_Pnt& root, const gp_Pnt& tip) {
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

/// The upper and the lower skin.
inline TopoDS_Face upperSkin() { return skin(0.08, kUpperRoot, kUpperTip); }
inline TopoDS_Face lowerSkin() { return skin(-0.06, kLowerRoot, kLowerTip); }

/// The upper skin and a copy of it moved by `shift`, as one skin: two wings apart, as a box
/// wing's lower and upper wing.
inline TopoDS_Shape upperSkinWithCopy(const gp_Vec& shift) {
  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, upperSkin());
  gp_Trsf move;
  move.SetTranslation(shift);
  builder.Add(both, upperSkin().Moved(TopLoc_Location(move)));
  return both;
}

}  // namespace airshape::test
