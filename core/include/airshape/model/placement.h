#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include <gp_Pnt.hxx>

#include "airshape/geometry/affine.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::model {

/// An affine map of 3-D points (CPACS transformations scale non-uniformly).
using Transform = geometry::Affine3;

/// A point moved by a transform.
gp_Pnt apply(const Transform& transform, const gp_Pnt& point);

/// The matrix of one <transformation>: T · Rx(a) · Ry(b) · Rz(c) · S, angles in degrees;
/// a missing element is the identity, a missing coordinate of a present one is 0 (the
/// convention the reference applies, even to scaling). Null gives the identity.
Transform transformationMatrix(const schema::TransformationType* transformation);

/// The component matrix C of a component its plugin declares placed by its own transformation
/// (graph::ComponentLocation::placedByTransformation): that transformation, translated by its
/// parent's origin (through the whole parentUID chain) unless its translation's refType is
/// absGlobal. Rotation and scaling of the parent are not inherited. The identity for any other.
Transform componentTransform(const Configuration& configuration, const std::string& uid);

/// The placement of an element with a transformation of its own and a parent that is a
/// component (elements placed in or on others): its matrix, translated by
/// the parent's origin (as componentTransform translates) unless there is no parent or its
/// translation is absGlobal.
Transform placedOnParent(const Configuration& configuration, const schema::TransformationType* transformation,
                         const std::string& parentUid);

/// A number the geometry is built from. NaN and INF are numbers to XML Schema, but no
/// geometry can be built from them: Error(InvalidModel) naming `xpath`.
double finite(double value, const std::string& xpath);

/// A relative coordinate the geometry is placed by (an eta or xsi, a share of a chord):
/// Error(InvalidModel) naming `xpath` where it is not a number in [0, 1].
double fraction(double value, const std::string& xpath);

/// Numbers of a CPACS vector text ("1;2.5;3"). Throws Error(InvalidModel) naming `xpath`.
std::vector<double> parseVector(const std::string& text, const std::string& xpath);

}  // namespace airshape::model
