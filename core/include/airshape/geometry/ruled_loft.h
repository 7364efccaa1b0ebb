#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

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
