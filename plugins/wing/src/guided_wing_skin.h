#pragma once

#include <memory>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>

#include "airshape/geometry/loft_piece.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::wing {

struct WingSegment;

/// The skin of a wing with guide curves: the Gordon surface through its airfoils and its
/// guides (CONVENTIONS §4.2, §9). Each airfoil is taken whole, as one curve over [0, 2]
/// from the lower trailing-edge end (0) to the leading edge (1) to the upper end (2);
/// relative circumference −1..0 runs along the lower side and 0..1 along the upper side,
/// each by its own length.
class GuidedWingSkin {
 public:
  /// The skin, or null when no segment of the wing has guide curves.
  static std::shared_ptr<const GuidedWingSkin> build(const Configuration& configuration, const schema::WingType& wing,
                                                     const std::vector<WingSegment>& segments);

  /// The point at eta of the segment where the two airfoils have xsi on their upper
  /// (lower) side: xsi is found on the skin at both sections and blended by eta.
  gp_Pnt upperPoint(std::size_t segment, double eta, double xsi) const;
  gp_Pnt lowerPoint(std::size_t segment, double eta, double xsi) const;

  /// The segment's B-rep: skin, blunt trailing edge, caps and solid.
  geometry::LoftPiece segmentPiece(std::size_t segment) const;

 private:
  gp_Pnt pointAt(std::size_t segment, double eta, double wholeParameter) const;
  /// The skin's u where airfoil `section` has whole-airfoil parameter t.
  double uAt(std::size_t section, double wholeParameter) const;

  Handle(Geom_BSplineSurface) surface_;
  std::vector<Handle(Geom_BSplineCurve)> airfoils_;      ///< whole, global, in chain order
  std::vector<double> sectionSites_;                     ///< the surface's v at each airfoil
  std::vector<double> guideSites_;                       ///< the surface's u at each guide, ascending
  std::vector<std::vector<double>> crossingParameters_;  ///< per airfoil, its parameter at each guide
  bool blunt_ = false;
};

}  // namespace airshape::wing
