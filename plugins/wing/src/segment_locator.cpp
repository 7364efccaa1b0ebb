#include "segment_locator.h"

#include <BRepClass3d_SolidClassifier.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>

namespace airshape::wing {

namespace {

/// The distance at which a point still counts as on a segment or on its upper skin, in metres.
constexpr double kOnTolerance = 0.03;

struct Projection {
  double u = 0, v = 0, distance = HUGE_VAL;
};

Projection project(const TopoDS_Face& face, const gp_Pnt& point) {
  Projection result;
  if (face.IsNull()) return result;
  GeomAPI_ProjectPointOnSurf projector(point, BRep_Tool::Surface(face));
  if (projector.NbPoints() == 0) return result;
  projector.LowerDistanceParameters(result.u, result.v);
  result.distance = projector.LowerDistance();
  return result;
}

/// Distance from the point to the segment's bilinear chord surface, by its own projection.
double chordDistance(const WingGeometry& geometry, std::size_t segment, const gp_Pnt& point) {
  // The chord surface is bilinear in (eta, xsi): a few Newton steps from its middle suffice.
  double eta = 0.5, xsi = 0.5;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const gp_Pnt p = geometry.chordPoint(segment, eta, xsi);
    const double h = 1e-6;
    const gp_Vec de(geometry.chordPoint(segment, eta - h, xsi), geometry.chordPoint(segment, eta + h, xsi));
    const gp_Vec dx(geometry.chordPoint(segment, eta, xsi - h), geometry.chordPoint(segment, eta, xsi + h));
    const gp_Vec r(point, p), e = de / (2 * h), x = dx / (2 * h);
    const double a = e.Dot(e), b = e.Dot(x), c = x.Dot(x), det = a * c - b * b;
    if (!(det > 0)) break;
    const double ge = r.Dot(e), gx = r.Dot(x);
    eta = std::clamp(eta - (c * ge - b * gx) / det, 0.0, 1.0);
    xsi = std::clamp(xsi - (a * gx - b * ge) / det, 0.0, 1.0);
  }
  return geometry.chordPoint(segment, eta, xsi).Distance(point);
}

bool accepts(const WingGeometry& geometry, const WingShape& shape, std::size_t segment, const gp_Pnt& point) {
  const TopoDS_Shape& solid = shape.segmentSolid(segment);
  if (!solid.IsNull()) {
    BRepClass3d_SolidClassifier classifier(solid, point, kOnTolerance);
    if (classifier.State() == TopAbs_IN || classifier.State() == TopAbs_ON) return true;
  }
  return chordDistance(geometry, segment, point) <= kOnTolerance;
}

}  // namespace

std::optional<SegmentLocation> locateOnWing(const WingGeometry& geometry, const WingShape& shape, const gp_Pnt& point) {
  const std::size_t count = geometry.segments().size();
  for (std::size_t k = 0; k < count; ++k) {
    if (!accepts(geometry, shape, k, point)) continue;
    std::size_t chosen = k;
    auto nearest = [&](std::size_t s) {
      return std::min(project(shape.segments()[s].upper, point).distance,
                      project(shape.segments()[s].lower, point).distance);
    };
    if (k + 1 < count && accepts(geometry, shape, k + 1, point) && nearest(k + 1) < nearest(k)) chosen = k + 1;
    const Projection upper = project(shape.segments()[chosen].upper, point);
    const Projection lower = project(shape.segments()[chosen].lower, point);
    const Projection& used = lower.distance < upper.distance ? lower : upper;
    // The skins are ruled with u = xsi (from the leading edge) and v = eta.
    return SegmentLocation{chosen, used.v, used.u, upper.distance <= kOnTolerance};
  }
  return std::nullopt;
}

}  // namespace airshape::wing
