#include "nacelle_cowl.h"

#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <Eigen/Geometry>
#include <gp_Ax1.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "cowl_loft.h"
#include "cowl_parts.h"
#include "nacelle_profile.h"

namespace airshape::nacelle {

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kSamePoint = 1e-9;

/// Adds a curve to the wire, and the straight line to its start from the wire's end where
/// they differ.
class ProfileWire {
 public:
  void add(const Handle(Geom_BSplineCurve) & curve) {
    lineTo(curve->StartPoint());
    wire_.Add(BRepBuilderAPI_MakeEdge(curve).Edge());
    end_ = curve->EndPoint();
    started_ = true;
  }
  void lineTo(const gp_Pnt& point) {
    if (started_ && end_.Distance(point) > kSamePoint) wire_.Add(BRepBuilderAPI_MakeEdge(end_, point).Edge());
    end_ = point;
  }
  TopoDS_Wire closed(const gp_Pnt& start) {
    lineTo(start);
    return wire_.Wire();
  }

 private:
  BRepBuilderAPI_MakeWire wire_;
  gp_Pnt end_;
  bool started_ = false;
};

}  // namespace

model::Transform sectionTransform(const schema::NacelleSectionType& section) {
  const schema::TransformationType* t = section.transformation.get();
  double phi = 0.0, axial = 0.0, radius = 0.0;
  if (t && t->translation) {
    phi = t->translation->x.value_or(0.0);
    axial = t->translation->y.value_or(0.0);
    radius = t->translation->z.value_or(0.0);
  }
  // The profile point (x, 0, y) is already in the x-z plane: no turn of the x-y plane needed.
  model::Transform result = model::Transform::Identity();
  if (t && t->scaling)
    result =
        Eigen::Scaling(t->scaling->x.value_or(1.0), t->scaling->y.value_or(1.0), t->scaling->z.value_or(1.0)) * result;
  if (t && t->rotation) {
    result = Eigen::AngleAxisd(t->rotation->x.value_or(0.0) * kDegree, Eigen::Vector3d::UnitX()) * result;
    result = Eigen::AngleAxisd(t->rotation->y.value_or(0.0) * kDegree, Eigen::Vector3d::UnitY()) * result;
    result = Eigen::AngleAxisd(t->rotation->z.value_or(0.0) * kDegree, Eigen::Vector3d::UnitZ()) * result;
  }
  result = Eigen::AngleAxisd(phi * kDegree, Eigen::Vector3d::UnitX()) * result;
  result = Eigen::Translation3d(axial, -radius * std::sin(phi * kDegree), radius * std::cos(phi * kDegree)) * result;
  return result;
}

namespace {

/// The solid a closed wire in a half plane of the x axis sweeps about that axis.
TopoDS_Shape revolved(const TopoDS_Wire& wire, const std::string& where) {
  BRepBuilderAPI_MakeFace face(wire, true);
  if (!face.IsDone()) throw Error(ErrorCode::InvalidModel, "the profile does not enclose a plane region", {}, where);
  BRepPrimAPI_MakeRevol solid(face.Face(), gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)));
  if (!solid.IsDone()) throw Error(ErrorCode::InvalidModel, "the profile cannot be revolved", {}, where);
  return solid.Shape();
}

}  // namespace

TopoDS_Shape cowlSolid(const Configuration& configuration, const schema::NacelleCowlType& cowl) {
  if (!cowl.sections || cowl.sections->section.empty())
    throw Error(ErrorCode::InvalidModel, "the cowl has no sections", {}, cowl.xpath);
  if (cowl.sections->section.size() > 1) return loftedCowl(configuration, cowl);
  const schema::RotationCurveType* rotation = cowl.rotationCurve.get();
  Handle(Geom_BSplineCurve) inner = rotationPiece(configuration, cowl);
  // The lower side is kept up to startZetaBlending and from endZetaBlending on (arc length, placed).
  const PlacedProfile profile = placedProfile(configuration, cowl.sections->section[0]);
  const Handle(Geom_BSplineCurve)& lower = profile.lower;
  const double blendStart =
      parameterAtLengthShare(lower, lengthShare(rotation->startZetaBlending, rotation->xpath + "/startZetaBlending"));
  const double blendEnd =
      parameterAtLengthShare(lower, lengthShare(rotation->endZetaBlending, rotation->xpath + "/endZetaBlending"));

  // Closed in the half plane from the leading edge: the upper side, the trailing edge, the lower
  // side to startZetaBlending, a straight blending line to the inner curve's start (startZeta,
  // joined by name as the schema says), the inner curve, a straight line to endZetaBlending and on
  // to the leading edge.
  warnWhereTheMeridianCrosses(configuration, cowl, {profile}, inner);
  ProfileWire wire;
  wire.add(profile.upper);
  wire.add(curvePiece(lower, lower->FirstParameter(), blendStart));
  wire.add(inner);
  wire.add(curvePiece(lower, blendEnd, lower->LastParameter()));
  return revolved(wire.closed(lower->EndPoint()), cowl.xpath);
}

TopoDS_Shape centerCowlSolid(const Configuration& configuration, const schema::NacelleCenterCowlType& cowl) {
  const NacelleProfile curve = NacelleProfile::named(configuration, cowl.curveUID, true, cowl.xpath + "/curveUID");
  const Handle(Geom_BSplineCurve) shifted =
      geometry::transformed(curve.whole(), model::Transform(Eigen::Translation3d(cowl.xOffset, 0.0, 0.0)));
  // Closed along the axis: down from the curve's end, along the axis, up to its start.
  const gp_Pnt start = shifted->StartPoint(), end = shifted->EndPoint();
  ProfileWire wire;
  wire.add(shifted);
  wire.lineTo(gp_Pnt(end.X(), 0.0, 0.0));
  wire.lineTo(gp_Pnt(start.X(), 0.0, 0.0));
  return revolved(wire.closed(start), cowl.xpath);
}

}  // namespace airshape::nacelle
