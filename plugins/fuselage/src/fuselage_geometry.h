#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/geometry/loft_piece.h"
#include "airshape/model/placement.h"
#include "airshape/named_shape.h"
#include "fuselage_guide_curves.h"
#include "fuselage_profile.h"

namespace airshape {
class Configuration;
}

namespace airshape::fuselage {

/// One segment of a fuselage: its share [vStart, vEnd] of the fuselage's loft.
struct FuselageSegment {
  std::string uid;
  std::string xpath;  ///< where the segment is defined, for errors
  double vStart = 0.0, vEnd = 1.0;
};

/// A fuselage as the queries need it: one smooth loft through all its profiles (u is the
/// profile parameter zeta, v runs from nose to tail), cut into segments in chain order.
class FuselageGeometry {
 public:
  static std::shared_ptr<const FuselageGeometry> of(const Configuration& configuration,
                                                    const schema::FuselageType& fuselage);
  /// A duct is lofted as a fuselage is: sections of fuselage profiles, segments, positionings.
  static std::shared_ptr<const FuselageGeometry> of(const Configuration& configuration, const schema::DuctType& duct);
  /// A body defined as a fuselage is but placed by `placement` instead of a component
  /// transformation of its own (a tank vessel, placed by its tank).
  static std::shared_ptr<const FuselageGeometry> of(const Configuration& configuration,
                                                    const schema::FuselageType& body,
                                                    const model::Transform& placement);

  const std::vector<std::string>& segmentUids() const { return segmentUids_; }

  /// The loft's point at profile parameter zeta, eta of the way through the segment's v range.
  gp_Pnt point(std::size_t segment, double eta, double zeta) const;
  /// Length of the profile of the segment at eta (the closing edge of half profiles excluded).
  double circumference(std::size_t segment, double eta) const;
  double segmentVolume(std::size_t segment) const;
  double segmentSurfaceArea(std::size_t segment) const;
  double volume() const;
  /// The skin only: no caps, no symmetry faces.
  double surfaceArea() const;

  /// The whole fuselage as one solid: skins, symmetry faces, front and rear caps, named
  /// "<segment uID>/skin", "<segment uID>/symmetry", "<fuselage uID>/front" and "/rear".
  NamedShape solid(const std::string& fuselageUid) const;
  /// The same for closed profiles, its faces sharing their edges from the start
  /// (geometry/loft_shell.h) instead of sewn. Throws where that cannot be built.
  NamedShape solidOfSharedEdges(const std::string& fuselageUid) const;
  /// One segment's solid (a fuselage segment's shape): its skin, symmetry face and caps,
  /// named "<segment uID>/skin", "/symmetry", "/front" and "/rear".
  NamedShape segmentSolid(std::size_t segment) const;

 private:
  template <class Body>
  static std::shared_ptr<const FuselageGeometry> build(const Configuration& configuration, const Body& body,
                                                       const model::Transform& placement);

  /// Skins the placed profiles (chain order): the loft without guide curves.
  void loft(const std::vector<PlacedProfile>& sections);
  /// The skin through the placed profiles and the guide curves: patches (patchRings) for
  /// closed profiles and for half profiles with guides along both ends, else a Gordon
  /// surface.
  void loftWithGuides(const std::vector<PlacedProfile>& sections, const FuselageGuides& guides);
  /// The reference's skin with guide curves: per segment a ring of cells between
  /// neighbouring guides, each a patch of its four boundaries (geometry/coons_patches.h).
  void patchRings(const std::vector<PlacedProfile>& sections, const FuselageGuides& guides);
  /// Whether guides run along both ends of every (open) profile.
  bool guidesAlongBothEnds(const FuselageGuides& guides) const;
  void cutIntoSegments(const std::vector<std::string>& segmentXpaths);
  /// The loft's u where section k's profile has parameter zeta.
  double loftParameterOf(std::size_t section, double zeta) const;
  double vAt(std::size_t segment, double eta) const;
  /// The loft's skin between sections `from` and `to` (chain order) as one face.
  TopoDS_Face skinFace(std::size_t from, std::size_t to) const;
  /// The B-rep of the loft between sections `from` and `to`.
  geometry::LoftPiece piece(std::size_t from, std::size_t to) const;
  /// A segment's B-rep, built on first use: most queries need none.
  const geometry::LoftPiece& segmentPiece(std::size_t segment) const;

  Handle(Geom_BSplineSurface) loft_;
  std::vector<Handle(Geom_BSplineCurve)> profiles_;  ///< placed, in chain order
  std::vector<double> sectionSites_;                 ///< the loft's v at each profile
  bool guided_ = false;
  std::vector<Handle(Geom_BSplineCurve)> sectionIsoCurves_;  ///< with guides: the loft's curve at each profile
  /// With guides and closed profiles: per segment its ring of cells (cell l over u in
  /// [l, l+1], v = eta), and where each cell starts and ends in zeta (the guides' start
  /// positions, the first again plus one at the end).
  std::vector<Handle(Geom_BSplineSurface)> patchRows_;
  std::vector<double> cellParameters_;
  bool closedProfiles_ = true;
  std::string xpath_;  ///< where the fuselage is defined, for errors
  std::vector<FuselageSegment> segments_;
  std::vector<std::string> segmentUids_;
  /// The sum of a measure of every segment, the segments measured on every core (each
  /// guided segment is its own ring of patches, sewn into its own solid).
  double sumOverSegments(const std::function<double(std::size_t segment)>& measure) const;

  /// A segment's piece, built on first use, once, whichever thread asks first.
  struct CachedPiece {
    std::once_flag built;
    std::unique_ptr<geometry::LoftPiece> piece;
  };
  std::vector<std::unique_ptr<CachedPiece>> segmentPieces_;
};

}  // namespace airshape::fuselage
