#pragma once

#include <optional>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include "airshape/error.h"
#include "airshape/geometry/affine.h"

namespace airshape::geometry {

// Small B-rep building blocks for lofted components: ruled faces between profile curves,
// planar caps, sewing into a solid.

/// The tolerance of the edges, faces and vertices built here.
inline constexpr double kBrepTolerance = 1e-7;
/// Curve ends this close join; faces this close are sewn.
inline constexpr double kJoinTolerance = 1e-6;

/// The curve moved by an affine map (applied to its poles, which is exact for B-splines).
Handle(Geom_BSplineCurve) transformed(const Handle(Geom_BSplineCurve) & curve, const Affine3& transform);

/// The straight segment from a to b as a degree-1 B-spline over [0, 1].
Handle(Geom_BSplineCurve) straightLine(const gp_Pnt& a, const gp_Pnt& b);

/// A vertex at a point whose tolerance is `tolerance`: the ends of the curves that meet there
/// lie within it.
TopoDS_Vertex vertexWithin(const gp_Pnt& point, double tolerance);

/// The ruled surface joining the points of equal parameter of two curves over the same
/// range: u the curves' parameter, v from 0 on the first to 1 on the second.
Handle(Geom_BSplineSurface)
    ruledSurface(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & second);

/// The ruled face joining the points of equal parameter of two curves over the same range.
TopoDS_Face ruledFace(const Handle(Geom_BSplineCurve) & first, const Handle(Geom_BSplineCurve) & second);

/// The plane the points lie in within `flatness` (through their mean, normal to the direction
/// they spread least in); nothing for fewer than three points, points on one line, or points
/// off every plane.
std::optional<gp_Pln> planeThroughPoints(const std::vector<gp_Pnt>& points, double flatness);

/// The planar face bounded by curves that join end to end into a closed wire. Throws
/// Error when they are not planar.
TopoDS_Face planarFace(const std::vector<Handle(Geom_BSplineCurve)>& boundary);

/// How a sewn solid is turned outwards: by the sign of its rough volume, which also refuses a
/// solid of no volume, or by whether the point at infinity lies outside it (OCCT's
/// classification), far cheaper where faces are trimmed: OCCT integrates their volume over
/// every knot span of their surfaces. The volume decides where the classification cannot.
enum class Orienting { ByVolume, ByClassification };

/// Sews faces into a closed shell and makes it a solid, faces pointing outwards. Throws Error
/// when they do not close or (`Orienting::ByVolume`) enclose no volume.
/// `sewnFaces`, when given, receives the solid's face for each input face (null for null).
/// Edges within `tolerance` of each other are joined.
TopoDS_Shape sewnSolid(const std::vector<TopoDS_Face>& faces, std::vector<TopoDS_Face>* sewnFaces = nullptr,
                       double tolerance = kJoinTolerance, Orienting orienting = Orienting::ByVolume);

/// The planar face on a closed wire, sharing its edges, its normal turned so that the wire
/// runs anticlockwise about it. Throws Error when the wire is not planar, or encloses no
/// area where such a face would not be valid (a profile flattened to a line).
TopoDS_Face planarFace(const TopoDS_Wire& wire);

/// Whether a planar face encloses no area: on average thinner (its area over its boundary's
/// size) than a few join tolerances, as the cap of a profile flattened to a line.
bool enclosesNoArea(const TopoDS_Face& planarFace);

/// The error of a profile that encloses no area where no face can close it, naming
/// `cpacsPath` where given.
Error noAreaError(const std::string& cpacsPath = {});

/// What `outwards` does with a solid that encloses no volume, whose inside and outside cannot
/// be told apart: refuse it (a segment of zero length or thickness), or keep it as built
/// (a segment between two different profiles in one plane, a flat ring).
enum class FlatSolid { Refused, Kept };

/// The solid turned so that its faces point outwards (Boolean operations then see its
/// inside); throws Error when it encloses no volume, unless `flat` keeps it.
TopoDS_Solid outwards(TopoDS_Solid solid, FlatSolid flat = FlatSolid::Refused);

}  // namespace airshape::geometry
