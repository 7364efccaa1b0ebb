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

/// The ruled loft between two closed profiles, each a loop of B-spline curves joined end
/// to end (curve k of one to curve k of the other, over the same parameter range and run
/// the same way round), closed by planar caps: one shell with shared edges, no sewing,
/// oriented outwards. `sides[k]` is the ruled face of curve k, its surface the one of
/// ruledFace (u the curves' parameter, v from the first profile to the last). Throws Error
/// when the curves do not close or correspond, a profile is not planar or the solid
/// encloses no volume.
struct RuledLoft {
  TopoDS_Shape solid;
  TopoDS_Face firstCap, lastCap;
  std::vector<TopoDS_Face> sides;
};
RuledLoft ruledLoft(const std::vector<Handle(Geom_BSplineCurve)>& first,
                    const std::vector<Handle(Geom_BSplineCurve)>& last);

}  // namespace airshape::geometry
