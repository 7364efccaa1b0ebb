#include "wing_measures.h"

#include <algorithm>
#include <cmath>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <Bnd_Box.hxx>
#include <Precision.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Vec.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"

namespace airshape::wing {

namespace {

/// The point with the coordinate normal to the plane set to zero.
gp_Pnt projected(gp_Pnt p, const std::string& plane) {
  if (plane == "x-y") p.SetZ(0.0);
  if (plane == "x-z") p.SetY(0.0);
  if (plane == "y-z") p.SetX(0.0);
  return p;
}

/// Index (0 = x, 1 = y, 2 = z) of the axis along which the wing spans.
int majorAxis(const WingGeometry& wing, const std::string& symmetry) {
  if (symmetry == "x-z") return 1;
  if (symmetry == "x-y") return 2;
  if (symmetry == "y-z") return 0;
  gp_XYZ depth(0, 0, 0), spread(0, 0, 0);
  auto absolute = [](const gp_XYZ& v) { return gp_XYZ(std::abs(v.X()), std::abs(v.Y()), std::abs(v.Z())); };
  for (const WingSegment& s : wing.segments()) {
    depth += absolute(s.inner.trailingEdge().XYZ() - s.inner.leadingEdge().XYZ());
    spread += absolute(s.outer.leadingEdge().XYZ() - s.inner.leadingEdge().XYZ());
  }
  if (!wing.segments().empty())
    depth +=
        absolute(wing.segments().back().outer.trailingEdge().XYZ() - wing.segments().back().outer.leadingEdge().XYZ());
  const double d[3] = {depth.X(), depth.Y(), depth.Z()}, s[3] = {spread.X(), spread.Y(), spread.Z()};
  const int deepest = d[0] >= d[1] && d[0] >= d[2] ? 0 : (d[1] >= d[2] ? 1 : 2);
  const int a = (deepest + 1) % 3, b = (deepest + 2) % 3;
  const int first = std::min(a, b), second = std::max(a, b);
  return s[second] > s[first] ? second : first;  // ties go to the lower axis (y before z)
}

/// The reference measures spans on wires tessellated with this deflection: the box is that
/// of the polygon's nodes, enlarged by the deflection and the edges' tolerance (OCCT's
/// BRepBndLib), so only the same tessellation of the same curves gives its numbers.
constexpr double kSpanDeflection = 1e-4;

/// The deflection an outline is tessellated with: the reference's 1e-4 for every real
/// airfoil (up to a kilometre across), a share of its size beyond, so that an absurdly
/// large outline (a coefficient of 1e300) is tessellated in finitely many steps.
double spanDeflection(const TopoDS_Wire& outline) {
  Bnd_Box box;
  BRepBndLib::Add(outline, box);
  if (box.IsVoid()) return kSpanDeflection;
  return std::max(kSpanDeflection, 1e-7 * std::sqrt(box.SquareExtent()));
}

/// A section's airfoil outline where the span measures it (closed by the trailing edge
/// when blunt), as one wire.
TopoDS_Wire placedOutline(const SegmentEnd& end, const model::Transform& unparented) {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (const Handle(Geom_BSplineCurve) & curve : end.profile->outline())
    curves.push_back(geometry::transformed(curve, unparented * end.transform));
  BRepBuilderAPI_MakeWire wire;
  for (const Handle(Geom_BSplineCurve) & curve : curves) wire.Add(BRepBuilderAPI_MakeEdge(curve).Edge());
  const gp_Pnt first = curves.front()->StartPoint(), last = curves.back()->EndPoint();
  if (first.Distance(last) > Precision::Confusion()) wire.Add(BRepBuilderAPI_MakeEdge(last, first).Edge());
  return wire.Wire();
}

/// The mirror in a symmetry plane ("x-y", "x-z" or "y-z").
gp_Trsf mirror(const std::string& symmetry) {
  const gp_Dir normal = symmetry == "x-y" ? gp_Dir(0, 0, 1) : symmetry == "x-z" ? gp_Dir(0, 1, 0) : gp_Dir(1, 0, 0);
  gp_Trsf transformation;
  transformation.SetMirror(gp_Ax2(gp_Pnt(0, 0, 0), normal));
  return transformation;
}

}  // namespace

double referenceArea(const WingGeometry& wing, const std::string& plane) {
  if (plane != "x-y" && plane != "x-z" && plane != "y-z")
    throw Error(ErrorCode::InvalidArgument, "plane must be \"x-y\", \"x-z\" or \"y-z\", not \"" + plane + "\"");
  double area = 0.0;
  for (std::size_t k = 0; k < wing.segments().size(); ++k) {
    const gp_Pnt a = projected(wing.chordPoint(k, 1, 0), plane), b = projected(wing.chordPoint(k, 1, 1), plane);
    const gp_Pnt c = projected(wing.chordPoint(k, 0, 1), plane), d = projected(wing.chordPoint(k, 0, 0), plane);
    area += 0.5 * gp_Vec(a, c).Crossed(gp_Vec(b, d)).Magnitude();
  }
  return area;
}

MeanAerodynamicChord meanAerodynamicChord(const WingGeometry& wing) {
  double weights = 0.0, weightedChord = 0.0;
  gp_XYZ weightedPoint(0, 0, 0);
  for (std::size_t k = 0; k < wing.segments().size(); ++k) {
    const gp_Pnt iL = wing.chordPoint(k, 0, 0), iT = wing.chordPoint(k, 0, 1);
    const gp_Pnt oL = wing.chordPoint(k, 1, 0), oT = wing.chordPoint(k, 1, 1);
    const double ci = iL.Distance(iT), co = oL.Distance(oT);
    auto yz = [](const gp_Pnt& p) { return gp_Pnt(0, p.Y(), p.Z()); };
    const double b = 0.5 * (yz(oL).Distance(yz(iL)) + yz(oT).Distance(yz(iT)));
    if (!(b > 0.0)) continue;  // a segment without span adds nothing
    const double b2 = 0.5 * ((oL.Y() - iL.Y()) + (oT.Y() - iT.Y()));
    const double bm = b * (2 * co + ci) / (3 * (co + ci));
    const double cm = ci - (ci - co) * bm / b;
    const gp_Pnt qi = wing.chordPoint(k, 0, 0.25), qo = wing.chordPoint(k, 1, 0.25);
    const double tanSweep = (qo.X() - qi.X()) / b, sinDihedral = (qo.Z() - qi.Z()) / b, cosDihedral = b2 / b;
    const gp_XYZ p = iL.XYZ() + gp_XYZ(0.25 * ci - 0.25 * cm + bm * tanSweep, bm * cosDihedral, bm * sinDihedral);
    const double area = (ci + co) * b / 2.0;
    weights += area;
    weightedChord += cm * area;
    weightedPoint += area * p;
  }
  if (!(weights > 0.0))
    throw Error(ErrorCode::InvalidModel, "the wing has no span, so no mean aerodynamic chord", {}, wing.xpath());
  return {weightedChord / weights, gp_Pnt(weightedPoint / weights)};
}

double span(const WingGeometry& wing, const std::string& symmetry, const model::Transform& unparented) {
  Bnd_Box box;
  for (const WingSegment& s : wing.segments())
    for (const SegmentEnd* end : {&s.inner, &s.outer}) {
      const TopoDS_Wire outline = placedOutline(*end, unparented);
      BRepMesh_IncrementalMesh tessellation(outline, spanDeflection(outline));
      BRepBndLib::Add(outline, box);
      if (symmetry != "none") BRepBndLib::Add(BRepBuilderAPI_Transform(outline, mirror(symmetry)).Shape(), box);
    }
  if (box.IsVoid()) return 0.0;
  double xmin, ymin, zmin, xmax, ymax, zmax;
  box.Get(xmin, ymin, zmin, xmax, ymax, zmax);
  const double extent[3] = {xmax - xmin, ymax - ymin, zmax - zmin};
  return extent[majorAxis(wing, symmetry)];
}

}  // namespace airshape::wing
