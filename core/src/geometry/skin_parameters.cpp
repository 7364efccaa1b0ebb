#include "airshape/geometry/skin_parameters.h"

#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/skinning.h"

namespace airshape::geometry {

std::vector<double> skinParameters(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  std::vector<Handle(Geom_BSplineCurve)> compatible;
  for (const auto& curve : curves) compatible.push_back(Handle(Geom_BSplineCurve)::DownCast(curve->Copy()));
  geometry::makeCompatible(compatible);
  return geometry::averagedSectionParameters(compatible);
}

}  // namespace airshape::geometry
