#include "wing_measures.h"

#include <cmath>

#include <Bnd_Box.hxx>
#include <gp_Vec.hxx>

#include "airshape/error.h"

namespace airshape::wing {

namespace {

/// The point with the coordinate normal to the plane set to zero.
gp_Pnt projected(gp_Pnt p, const std::string& plane) {
  if (plane == "x-y") p.SetZ(0.0);
  if (plane == "x-z") p.SetY(0.0);
  if (plane == "y-z") p.SetX(0.0);
  return p;
}

gp_Pnt mirrored(gp_Pnt p, const std::string& symmetry) {
  if (symmetry == "x-z") p.SetY(-p.Y());
  if (symmetry == "x-y") p.SetZ(-p.Z());
  if (symmetry == "y-z") p.SetX(-p.X());
  return p;
}

gp_Pnt moved(const model::Transform& transform, const gp_Pnt& p) {
  const Eigen::Vector3d v = transform * Eigen::Vector3d(p.X(), p.Y(), p.Z());
  return gp_Pnt(v.x(), v.y(), v.z());
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
  if (!(weights > 0.0)) throw Error(ErrorCode::InvalidModel, "the wing has no span, so no mean aerodynamic chord");
  return {weightedChord / weights, gp_Pnt(weightedPoint / weights)};
}

double span(const WingGeometry& wing, const std::string& symmetry, const model::Transform& unparented) {
  constexpr int kSamples = 200;
  Bnd_Box box;
  auto add = [&](const SegmentEnd& end) {
    for (int i = 0; i <= kSamples; ++i) {
      const double xsi = static_cast<double>(i) / kSamples;
      for (const gp_Pnt& p : {end.upper(xsi), end.lower(xsi)}) {
        const gp_Pnt q = moved(unparented, p);
        box.Add(q);
        if (symmetry != "none") box.Add(mirrored(q, symmetry));
      }
    }
  };
  for (const WingSegment& s : wing.segments()) {
    add(s.inner);
    add(s.outer);
  }
  if (box.IsVoid()) return 0.0;
  double xmin, ymin, zmin, xmax, ymax, zmax;
  box.Get(xmin, ymin, zmin, xmax, ymax, zmax);
  const double extent[3] = {xmax - xmin, ymax - ymin, zmax - zmin};
  // The definition is the box of the profile wires tessellated with deflection 1e-4 and
  // enlarged, as OCCT's BRepBndLib does, by that deflection plus the edge tolerance (1e-7)
  // on each side.
  constexpr double kBoxEnlargement = 1e-4 + 1e-7;
  return extent[majorAxis(wing, symmetry)] - 2.0 * box.GetGap() + 2.0 * kBoxEnlargement;
}

}  // namespace airshape::wing
