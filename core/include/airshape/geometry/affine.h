#pragma once

// Eigen's 3D affine transform, named without Eigen's headers: parsing <Eigen/Geometry> costs about
// a second in every source, and most sources that see a transform only pass it on. Sources that
// compute with one include <Eigen/Geometry> themselves (docs/building.md).

namespace Eigen {
template <typename Scalar, int Dim, int Mode, int Options>
class Transform;
}  // namespace Eigen

namespace airshape::geometry {

/// Eigen::Affine3d: Transform<double, 3, Affine (2), AutoAlign (0)>; a test asserts the two agree.
using Affine3 = Eigen::Transform<double, 3, 2, 0>;

}  // namespace airshape::geometry
