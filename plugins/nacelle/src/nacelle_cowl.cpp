#include "nacelle_cowl.h"

#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <gp_Ax1.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "nacelle_profile.h"

namespace airshape::nacelle {

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kSamePoint = 1e-9;

Handle(Geom_BSplineCurve) placed(const Handle(Geom_BSplineCurve) & curve, const model::Transform& transform) {
  Handle(Geom_BSplineCurve) copy = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  for (int i = 1; i <= copy->NbPoles(); ++i) copy->SetPole(i, model::apply(transform, copy->Pole(i)));
  return copy;
}

/// A curve coordinate of the range [−1, 0] as a share of arc length from the curve's start.
double lengthShare(double zeta, const std::string& where) {
  if (zeta < -1.0 || zeta > 0.0)
    throw Error(ErrorCode::InvalidModel, "zeta " + std::to_string(zeta) + " is outside [-1, 0]", {}, where);
  return zeta + 1.0;
}

const schema::NacelleSectionType& sectionNamed(const schema::NacelleCowlType& cowl, const std::string& uid,
                                               const std::string& where) {
  for (const auto& section : cowl.sections->section)
    if (section.uID == uid) return section;
  throw Error(ErrorCode::InvalidModel, "'" + uid + "' names no section of this cowl", {}, where);
}

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
  if (cowl.sections->section.size() > 1)
    throw Error(ErrorCode::NotImplemented,
                "cowls of " + std::to_string(cowl.sections->section.size()) +
                    " sections (lofted around the engine along guide curves) are not built yet",
                {}, cowl.xpath + "/sections");
  if (!cowl.rotationCurve) throw Error(ErrorCode::InvalidModel, "the cowl has no rotation curve", {}, cowl.xpath);
  const schema::NacelleSectionType& section = cowl.sections->section[0];
  const schema::RotationCurveType& rotation = *cowl.rotationCurve;
  const std::string rotationPath = rotation.xpath;

  // The section's lower side without its blending part: the lower side runs from the trailing
  // edge, zeta −1, to the leading edge, zeta 0 (arc length, placed); it is kept up to
  // startZetaBlending and from endZetaBlending on.
  const model::Transform placement = sectionTransform(section);
  const NacelleProfile profile =
      NacelleProfile::named(configuration, section.profileUID, false, section.xpath + "/profileUID");
  Handle(Geom_BSplineCurve) lower = placed(profile.lower(), placement);
  const double blendStart =
      parameterAtLengthShare(lower, lengthShare(rotation.startZetaBlending, rotationPath + "/startZetaBlending"));
  const double blendEnd =
      parameterAtLengthShare(lower, lengthShare(rotation.endZetaBlending, rotationPath + "/endZetaBlending"));

  // The rotation curve between startZeta and endZeta, placed like its reference section. Its
  // curve coordinate runs as a lower side's: −1 at its last point, 0 at its first (arc length in
  // its own plane), so that startZeta faces startZetaBlending.
  const NacelleProfile curve =
      NacelleProfile::named(configuration, rotation.curveProfileUID, true, rotationPath + "/curveProfileUID");
  Handle(Geom_BSplineCurve) backwards = Handle(Geom_BSplineCurve)::DownCast(curve.whole()->Copy());
  backwards->Reverse();
  const double from = parameterAtLengthShare(backwards, lengthShare(rotation.startZeta, rotationPath + "/startZeta"));
  const double to = parameterAtLengthShare(backwards, lengthShare(rotation.endZeta, rotationPath + "/endZeta"));
  Handle(Geom_BSplineCurve) inner =
      placed(curvePiece(backwards, from, to),
             sectionTransform(sectionNamed(cowl, rotation.referenceSectionUID, rotationPath + "/referenceSectionUID")));

  // Closed in the half plane from the leading edge: the upper side, the trailing edge, the lower
  // side to startZetaBlending, the inner curve from its end nearer that point (joined by a
  // straight blending line), and from endZetaBlending on to the leading edge.
  ProfileWire wire;
  wire.add(placed(profile.upper(), placement));
  wire.add(curvePiece(lower, lower->FirstParameter(), blendStart));
  const gp_Pnt startBlend = lower->Value(blendStart);
  if (startBlend.Distance(inner->EndPoint()) < startBlend.Distance(inner->StartPoint())) inner->Reverse();
  wire.add(inner);
  wire.add(curvePiece(lower, blendEnd, lower->LastParameter()));
  return revolved(wire.closed(lower->EndPoint()), cowl.xpath);
}

TopoDS_Shape centerCowlSolid(const Configuration& configuration, const schema::NacelleCenterCowlType& cowl) {
  const NacelleProfile curve = NacelleProfile::named(configuration, cowl.curveUID, true, cowl.xpath + "/curveUID");
  const Handle(Geom_BSplineCurve) shifted =
      placed(curve.whole(), model::Transform(Eigen::Translation3d(cowl.xOffset, 0.0, 0.0)));
  // Closed along the axis: down from the curve's end, along the axis, up to its start.
  const gp_Pnt start = shifted->StartPoint(), end = shifted->EndPoint();
  ProfileWire wire;
  wire.add(shifted);
  wire.lineTo(gp_Pnt(end.X(), 0.0, 0.0));
  wire.lineTo(gp_Pnt(start.X(), 0.0, 0.0));
  return revolved(wire.closed(start), cowl.xpath);
}

}  // namespace airshape::nacelle
