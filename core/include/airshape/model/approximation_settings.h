#pragma once

#include <string>
#include <vector>

#include <xercesc/util/XercesDefs.hpp>

#include "airshape/geometry/curve_approximation.h"

XERCES_CPP_NAMESPACE_BEGIN
class DOMElement;
XERCES_CPP_NAMESPACE_END

namespace airshape::model {

/// What a point list's `approximationSettings` (the reference's extension, outside CPACS 3.5,
/// for airfoils and profiles) ask for: a least-squares cubic with `poles`
/// control points instead of the interpolating one, its error measured as `measure`, passing
/// exactly through the points `interpolated` (0-based, in the file's order).
struct ApproximationSettings {
  int poles = 0;
  geometry::FitError measure = geometry::FitError::RootMeanSquare;
  std::vector<int> interpolated;
};

/// Reads the settings element (`xpath` names it) of a list of `pointCount` points. Throws
/// Error naming the node for what cannot be met: no controlPointNumber (a maximumError alone
/// is not supported), fewer than four poles or more poles than points, fractional counts or
/// indices, indices (1-based in the file) outside the list, an errorComputationMethod other
/// than RMSE (the default) or MaxError.
ApproximationSettings approximationSettings(const xercesc::DOMElement& settings, const std::string& xpath,
                                            int pointCount);

}  // namespace airshape::model
