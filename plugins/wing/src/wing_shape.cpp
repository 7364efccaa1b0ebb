#include "wing_shape.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/skinning.h"

namespace airshape::wing {

namespace {

constexpr double kTolerance = 1e-7;
/// Relative accuracy of the Gauss-Kronrod integration of volumes and areas.
constexpr double kIntegrationAccuracy = 1e-9;

Handle(Geom_BSplineCurve) placed(const Handle(Geom_BSplineCurve) & curve, const model::Transform& transform) {
  Handle(Geom_BSplineCurve) moved = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  for (int i = 1; i <= moved->NbPoles(); ++i) {
    const gp_Pnt& p = moved->Pole(i);
    const Eigen::Vector3d q = transform * Eigen::Vector3d(p.X(), p.Y(), p.Z());
    moved->SetPole(i, gp_Pnt(q.x(), q.y(), q.z()));
  }
  return moved;
}

Handle(Geom_BSplineCurve) line(const gp_Pnt& a, const gp_Pnt& b) {
  TColgp_Array1OfPnt poles(1, 2);
  poles(1) = a;
  poles(2) = b;
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0.0;
  knots(2) = 1.0;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(2);
  return new Geom_BSplineCurve(poles, knots, multiplicities, 1);
}

TopoDS_Face ruled(const Handle(Geom_BSplineCurve) & inner, const Handle(Geom_BSplineCurve) & outer) {
  const std::vector<double> sites = {0.0, 1.0};
  const auto surface = geometry::skinCurves({inner, outer}, sites, geometry::skinningSpace(sites, 1, false));
  return BRepBuilderAPI_MakeFace(surface, kTolerance).Face();
}

/// The three (or two) curves of a placed airfoil: upper, lower and the blunt trailing edge.
struct PlacedAirfoil {
  Handle(Geom_BSplineCurve) upper, lower, trailingEdge;
};

PlacedAirfoil placedAirfoil(const SegmentEnd& end) {
  PlacedAirfoil airfoil{
      placed(end.profile->upperCurve(), end.transform), placed(end.profile->lowerCurve(), end.transform), {}};
  if (end.profile->bluntTrailingEdge())
    airfoil.trailingEdge = line(airfoil.upper->EndPoint(), airfoil.lower->EndPoint());
  return airfoil;
}

TopoDS_Face cap(const PlacedAirfoil& airfoil, const std::string& where) {
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(airfoil.upper).Edge());
  if (!airfoil.trailingEdge.IsNull()) wire.Add(BRepBuilderAPI_MakeEdge(airfoil.trailingEdge).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(airfoil.lower).Edge());
  BRepBuilderAPI_MakeFace face(wire.Wire(), true);
  if (!face.IsDone())
    throw Error(ErrorCode::InvalidModel, "the " + where + " airfoil is not planar, so no cap closes it");
  return face.Face();
}

double area(const TopoDS_Shape& shape) {
  if (shape.IsNull()) return 0.0;
  GProp_GProps properties;
  BRepGProp::SurfaceProperties(shape, properties, kIntegrationAccuracy);
  return properties.Mass();
}

SegmentShape segmentShape(const WingSegment& segment) {
  const PlacedAirfoil inner = placedAirfoil(segment.inner), outer = placedAirfoil(segment.outer);
  if (inner.trailingEdge.IsNull() != outer.trailingEdge.IsNull())
    throw Error(ErrorCode::InvalidModel, "segment '" + segment.uid + "' joins a blunt and a sharp trailing edge");
  SegmentShape shape;
  shape.upper = ruled(inner.upper, outer.upper);
  shape.lower = ruled(inner.lower, outer.lower);
  if (!inner.trailingEdge.IsNull()) shape.trailingEdge = ruled(inner.trailingEdge, outer.trailingEdge);
  shape.innerCap = cap(inner, "inner");
  shape.outerCap = cap(outer, "outer");
  BRepBuilderAPI_Sewing sewing(1e-6);
  for (const TopoDS_Face& face : {shape.upper, shape.lower, shape.trailingEdge, shape.innerCap, shape.outerCap})
    if (!face.IsNull()) sewing.Add(face);
  sewing.Perform();
  TopExp_Explorer shells(sewing.SewedShape(), TopAbs_SHELL);
  if (!shells.More()) throw Error(ErrorCode::InvalidModel, "segment '" + segment.uid + "' does not close into a solid");
  shape.solid = BRepBuilderAPI_MakeSolid(TopoDS::Shell(shells.Current())).Solid();
  return shape;
}

}  // namespace

std::shared_ptr<const WingShape> WingShape::of(const Configuration& configuration, const schema::WingType& wing) {
  return configuration.cache().obtain<WingShape>("wing-shape:" + wing.uID, [&] {
    auto shape = std::make_shared<WingShape>();
    for (const WingSegment& segment : WingGeometry::of(configuration, wing)->segments())
      shape->segments_.push_back(segmentShape(segment));
    return std::shared_ptr<const WingShape>(shape);
  });
}

double WingShape::segmentVolume(std::size_t segment) const {
  GProp_GProps properties;
  BRepGProp::VolumeProperties(segments_[segment].solid, properties, kIntegrationAccuracy);
  return std::abs(properties.Mass());
}

double WingShape::segmentSurfaceArea(std::size_t segment) const {
  return area(segments_[segment].upper) + area(segments_[segment].lower);
}

double WingShape::volume() const {
  double total = 0.0;
  for (std::size_t k = 0; k < segments_.size(); ++k) total += segmentVolume(k);
  return total;
}

double WingShape::surfaceArea() const {
  if (segments_.empty()) return 0.0;
  double total = area(segments_.front().innerCap) + area(segments_.back().outerCap);
  for (std::size_t k = 0; k < segments_.size(); ++k) total += segmentSurfaceArea(k) + area(segments_[k].trailingEdge);
  return total;
}

}  // namespace airshape::wing
