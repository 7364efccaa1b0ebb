#pragma once

#include <vector>

#include <Eigen/Geometry>
#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

namespace airshape::geometry {

// Small B-rep building blocks for lofted components: ruled faces between profile curves,
// planar caps, sewing into a solid.

/// The curve moved by an affine map (applied to its poles, which is exact for B-splines).
Handle(Geom_BSplineCurve) transformed(const Handle(Geom_BSplineCurve) & curve, const Eigen::Affine3d& transform);

/// The straight segment from a to b as a degree-1 B-spline over [0, 1].
Handle(Geom_BSplineCurve) straightLine(const gp_Pnt& a, const gp_Pnt& b);

/// The ruled face joining the points of equal parameter of two curves over the same range.
TopoDS_Face ruledFace(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & second);

/// The planar face bounded by curves that join end to end into a closed wire. Throws
/// Error when they are not planar.
TopoDS_Face planarFace(const std::vector<Handle(Geom_BSplineCurve)>& boundary);

/// Sews faces into a closed shell and makes it a solid, faces pointing outwards. Throws Error
/// when they do not close or enclose no volume.
/// `sewnFaces`, when given, receives the solid's face for each input face (null for null).
TopoDS_Shape sewnSolid(const std::vector<TopoDS_Face>& faces, std::vector<TopoDS_Face>* sewnFaces = nullptr);

/// The ruled loft between two closed wires of B-spline edges (edge k to edge k, as OCCT's
/// ruled ThruSections joins them) closed by planar caps on the wires: one shell with shared
/// edges, no sewing, oriented outwards. Throws Error when a wire is not planar or the solid
/// encloses no volume.
struct RuledLoft {
  TopoDS_Shape solid;
  TopoDS_Face firstCap, lastCap;
};
RuledLoft ruledLoft(const TopoDS_Wire& first, const TopoDS_Wire& last);

}  // namespace airshape::geometry
