#pragma once

#include <memory>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/model/placement.h"
#include "fuselage_profile.h"

namespace airshape {
class Configuration;
}

namespace airshape::fuselage {

/// One segment of a fuselage: its two profile curves in global coordinates, the ruled skin
/// between them (and the flat symmetry face of half profiles), closed by planar caps.
struct FuselageSegment {
  std::string uid;
  Handle(Geom_BSplineCurve) start, end;  ///< placed profiles, made compatible
  bool closed = true;
  TopoDS_Face skin, symmetryFace, startCap, endCap;
  TopoDS_Shape solid;
  std::string solidProblem;  ///< why there is no solid (the points and lengths still work)
};

/// A fuselage as the queries need it: segments in chain order.
class FuselageGeometry {
 public:
  static std::shared_ptr<const FuselageGeometry> of(const Configuration& configuration,
                                                    const schema::FuselageType& fuselage);

  const std::vector<FuselageSegment>& segments() const { return segments_; }
  const std::vector<std::string>& segmentUids() const { return segmentUids_; }

  /// The point at (eta, zeta): the straight blend of the two profiles at curve parameter zeta.
  gp_Pnt point(std::size_t segment, double eta, double zeta) const;
  /// Length of the profile of the segment at eta (the closing edge of half profiles excluded).
  double circumference(std::size_t segment, double eta) const;
  double segmentVolume(std::size_t segment) const;
  double segmentSurfaceArea(std::size_t segment) const;
  double volume() const;
  /// The skin only: no caps, no symmetry faces.
  double surfaceArea() const;

  /// The whole fuselage as one solid: skins, symmetry faces, front and rear caps.
  TopoDS_Shape solid() const;

 private:
  std::vector<FuselageSegment> segments_;
  std::vector<std::string> segmentUids_;
};

}  // namespace airshape::fuselage
