#pragma once

#include <memory>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::wing {

struct WingSegment;

/// The skin of a wing with guide curves: one Coons patch per cell between neighbouring
/// airfoils and guides, as the reference builds it (CONVENTIONS §4.2, §9; see
/// geometry/coons_patches.h), one surface per segment. Each airfoil is taken whole, as one
/// curve over [0, 2] from the lower trailing-edge end (0) to the leading edge (1) to the
/// upper end (2); relative circumference −1..0 runs along the lower side and 0..1 along the
/// upper side, each by its own length.
class GuidedWingSkin {
 public:
  /// The skin, or null when no segment of the wing has guide curves.
  static std::shared_ptr<const GuidedWingSkin> build(const Configuration& configuration, const schema::WingType& wing,
                                                     const std::vector<WingSegment>& segments);

  /// The point at eta of the segment and xsi on its upper (lower) side: xsi counts as a
  /// relative circumference (negated on the lower side), mapped linearly onto the cell
  /// between the two guides around it; eta is the cell's parameter along the guides.
  gp_Pnt upperPoint(std::size_t segment, double eta, double xsi) const;
  gp_Pnt lowerPoint(std::size_t segment, double eta, double xsi) const;

  /// The segment's skin: its cells side by side, cell l over u in [l, l+1], v = eta.
  const Handle(Geom_BSplineSurface) & segmentSurface(std::size_t segment) const { return rows_[segment]; }
  /// Where the lower side ends on every segment surface: the u of the guide at the leading
  /// edge (relative circumference 0), or 0 when no guide runs there.
  double leadingEdgeU() const;
  bool bluntTrailingEdge() const { return blunt_; }

 private:
  gp_Pnt pointAt(std::size_t segment, double eta, double relativeCircumference) const;

  std::vector<Handle(Geom_BSplineCurve)> airfoils_;  ///< whole, global, in chain order
  std::vector<Handle(Geom_BSplineSurface)> rows_;    ///< per segment: cell l over u in [l, l+1], v = eta
  std::vector<double> relativeCircumferences_;       ///< of the guides at the root, ascending
  bool blunt_ = false;
};

}  // namespace airshape::wing
