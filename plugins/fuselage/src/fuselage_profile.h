#pragma once

#include <Geom_BSplineCurve.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::fuselage {

/// A fuselage profile in the y-z plane as one B-spline curve whose parameter over [0, 1] is
/// zeta, starting at the first point of the list. A closed profile (first and last point
/// within 0.5 % of its size) is periodic and smooth across its seam; an open one (a half
/// fuselage) is closed by a straight edge in the loft.
struct FuselageProfile {
  Handle(Geom_BSplineCurve) curve;
  bool closed = true;

  /// Throws Error naming the profile's CPACS path for a definition that gives no curve.
  static FuselageProfile fromDefinition(const schema::ProfileGeometryType& definition);
};

}  // namespace airshape::fuselage
