#pragma once

#include <functional>
#include <string>
#include <vector>

#include <xercesc/dom/DOMElement.hpp>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>

#include "airshape/problem.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::wing {

/// A wing airfoil in profile coordinates (x along the chord, z up, y ignored for the
/// chord): one curve split at the leading edge into an upper side (LE → upper TE end) and
/// a lower side (LE → lower TE end), plus the chord line. See docs/wing.md.
class WingProfile {
 public:
  /// One side as a function of its parameter xsi.
  using Side = std::function<gp_Pnt(double)>;

  /// Builds a profile from its CPACS definition (point list or CST). Throws Error naming
  /// the profile's CPACS path for a definition that gives no airfoil.
  static WingProfile fromDefinition(const schema::ProfileGeometryType& definition);

  /// The point at normalised parameter xsi in [0, 1] of the upper (lower) side: 0 is the
  /// leading edge, 1 the upper (lower) end of the trailing edge. On the lower side of a
  /// nacaProfile xsi runs the other way, from the trailing edge (0) to the leading edge (1),
  /// as the reference library's point queries have it for that type.
  gp_Pnt upper(double xsi) const;
  gp_Pnt lower(double xsi) const;

  /// The upper (lower) side as a B-spline curve over [0, 1] whose parameter is xsi.
  const Handle(Geom_BSplineCurve) & upperCurve() const { return upperCurve_; }
  const Handle(Geom_BSplineCurve) & lowerCurve() const { return lowerCurve_; }

  /// The airfoil's outline as the reference draws its wire, from the lower trailing-edge
  /// end over the leading edge to the upper end: a point list's one interpolated curve (in
  /// its own parameter), otherwise the lower side reversed and the upper side. A blunt
  /// trailing edge is not part of it.
  std::vector<Handle(Geom_BSplineCurve)> outline() const;

  const gp_Pnt& leadingEdge() const { return leadingEdge_; }
  const gp_Pnt& trailingEdge() const { return trailingEdge_; }
  bool bluntTrailingEdge() const { return blunt_; }
  /// What was odd but buildable about the definition (a point list that crosses itself by
  /// less than the tolerance), each naming its CPACS path.
  const Problems& warnings() const { return warnings_; }

 private:
  static WingProfile fromPointList(const schema::CurvePointListXYZType& points, const std::string& xpath);
  static WingProfile fromCst(const schema::Cst2DType& cst, const std::string& xpath);
  /// The reference library's nacaProfile (outside CPACS 3.5): a 4-digit NACA airfoil from
  /// the standard thickness and camber laws, evaluated exactly along each side.
  static WingProfile fromNaca(const xercesc::DOMElement& naca, const std::string& xpath);
  /// The reference's approximationSettings (outside CPACS 3.5): a least-squares cubic with
  /// controlPointNumber poles on uniform knots, passing exactly through both ends, the
  /// leading edge (at parameter 0.5) and the interpolatedPointsIndices (1-based), its sample
  /// parameters corrected towards the samples' feet as the reference corrects them.
  static WingProfile fromApproximatedPoints(std::vector<gp_Pnt> points, const xercesc::DOMElement& settings,
                                            const std::string& xpath);
  /// A profile with only its chord: the leading edge is the point at `leIndex` (the one
  /// farthest from the trailing-edge midpoint), the trailing edge the end point (sharp) or
  /// the less far aft end's place on the chord line (blunt). `points` run from the lower side.
  static WingProfile withChord(const std::vector<gp_Pnt>& points, std::size_t leIndex);
  /// An airfoil through points (any orientation), as a point list gives them.
  static WingProfile fromPoints(std::vector<gp_Pnt> points, const std::string& xpath);

  /// Both sides of an analytic airfoil (CST, NACA) as the curves the reference library makes
  /// of them: piecewise Chebyshev of the given degree, error 1e-5 of the chord. Points at a
  /// given xsi lie on these curves, so they agree with the reference's.
  void approximateSides(const Side& upper, const Side& lower, int degree);
  /// Both sides from one curve over [0, 1] running lower trailing edge -> leading edge (at
  /// parameter `leadingEdge`) -> upper trailing edge; xsi runs linearly in its parameter.
  void takeWholeCurve(const Handle(Geom_BSplineCurve) & curve, double leadingEdge);

  // Each side as a function of xsi (0 at the LE).
  Side upper_, lower_;
  Handle(Geom_BSplineCurve) upperCurve_, lowerCurve_;
  Handle(Geom_BSplineCurve) whole_;  ///< a point list's whole curve (the outline), else null
  gp_Pnt leadingEdge_, trailingEdge_;
  bool blunt_ = false;
  bool lowerXsiFromTrailingEdge_ = false;
  Problems warnings_;
};

}  // namespace airshape::wing
