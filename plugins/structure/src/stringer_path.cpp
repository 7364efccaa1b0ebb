#include "stringer_path.h"

#include <algorithm>
#include <cmath>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepFill.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include "airshape/error.h"
#include "fuselage_frame.h"

namespace airshape::structure {

namespace {

constexpr double kDegrees = M_PI / 180.0;

StringerPath::Ray blend(const StringerPath::Ray& a, const StringerPath::Ray& b, double share) {
  return {gp_Pnt(a.origin.XYZ() * (1.0 - share) + b.origin.XYZ() * share),
          a.direction * (1.0 - share) + b.direction * share};
}

}  // namespace

StringerPath::StringerPath(const schema::StringerType& stringer) : uid_(stringer.uID) {
  for (const schema::StringerFramePositionType& position : stringer.stringerPosition) {
    if (!position.positionX)
      throw Error(ErrorCode::NotImplemented, "stringer positions placed by a section element are not built yet", {},
                  position.xpath);
    const double angle = position.referenceAngle * kDegrees;
    positions_.push_back({gp_Pnt(*position.positionX, position.referenceY, position.referenceZ),
                          gp_Vec(0.0, -std::sin(angle), std::cos(angle))});
  }
  if (positions_.empty()) throw Error(ErrorCode::InvalidModel, "the stringer has no position", {}, stringer.xpath);
  std::stable_sort(positions_.begin(), positions_.end(),
                   [](const Ray& a, const Ray& b) { return a.origin.X() < b.origin.X(); });
}

StringerPath::Ray StringerPath::rayAt(double x) const {
  if (x <= positions_.front().origin.X()) {
    Ray ray = positions_.front();
    ray.origin.SetX(x);
    return ray;
  }
  for (std::size_t k = 1; k < positions_.size(); ++k) {
    const Ray& before = positions_[k - 1];
    const Ray& after = positions_[k];
    if (x > after.origin.X()) continue;
    const double run = after.origin.X() - before.origin.X();
    return run > 0.0 ? blend(before, after, (x - before.origin.X()) / run) : after;
  }
  Ray ray = positions_.back();
  ray.origin.SetX(x);
  return ray;
}

std::vector<TopoDS_Face> StringerPath::surface(const FuselageFrame& fuselage, double fromX, double toX,
                                               double length) const {
  // The stations where the surface bends: the ends and the positions between them.
  std::vector<double> stations{fromX};
  for (const Ray& position : positions_)
    if (position.origin.X() > fromX && position.origin.X() < toX) stations.push_back(position.origin.X());
  stations.push_back(toX);
  auto rayEdge = [&](double x) {
    const Ray ray = rayAt(x);
    // Both ends carried to the global frame, so that the ruled surfaces between the positions
    // are the same whatever the fuselage's transformation.
    return BRepBuilderAPI_MakeEdge(fuselage.toGlobal(ray.origin),
                                   fuselage.toGlobal(ray.origin.Translated(ray.direction * length)))
        .Edge();
  };
  std::vector<TopoDS_Face> faces;
  for (std::size_t k = 1; k < stations.size(); ++k)
    if (stations[k] > stations[k - 1]) faces.push_back(BRepFill::Face(rayEdge(stations[k - 1]), rayEdge(stations[k])));
  return faces;
}

}  // namespace airshape::structure
