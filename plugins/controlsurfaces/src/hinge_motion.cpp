#include "hinge_motion.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "airshape/error.h"
#include "airshape/model/placement.h"

namespace airshape::controlsurfaces {

namespace {

using Matrix = Eigen::Matrix3d;
using Vector = Eigen::Vector3d;

constexpr double kDegree = M_PI / 180.0;

Vector asVector(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

Matrix rotationX(double a) { return Eigen::AngleAxisd(a, Vector::UnitX()).toRotationMatrix(); }
Matrix rotationY(double a) { return Eigen::AngleAxisd(a, Vector::UnitY()).toRotationMatrix(); }
Matrix rotationZ(double a) { return Eigen::AngleAxisd(a, Vector::UnitZ()).toRotationMatrix(); }

/// The step values of one step, missing ones zero; a value that is not finite is an error
/// naming it.
StepValues valuesOf(const schema::ControlSurfaceStepType& step) {
  StepValues values;
  values.rotation = model::finite(step.hingeLineRotation.value_or(0.0), step.xpath + "/hingeLineRotation");
  if (step.innerHingeTranslation) {
    const schema::PointType& t = *step.innerHingeTranslation;
    values.innerTranslation.SetCoord(model::finite(t.x.value_or(0.0), t.xpath + "/x"),
                                     model::finite(t.y.value_or(0.0), t.xpath + "/y"),
                                     model::finite(t.z.value_or(0.0), t.xpath + "/z"));
  }
  if (const auto& outer = step.outerHingeTranslation)
    values.outerTranslation.SetCoord(model::finite(outer->x, outer->xpath + "/x"), values.innerTranslation.Y(),
                                     model::finite(outer->z, outer->xpath + "/z"));
  else
    values.outerTranslation.SetY(values.innerTranslation.Y());
  return values;
}

StepValues blend(const StepValues& a, const StepValues& b, double share) {
  return {(1.0 - share) * a.rotation + share * b.rotation,
          (1.0 - share) * a.innerTranslation + share * b.innerTranslation,
          (1.0 - share) * a.outerTranslation + share * b.outerTranslation};
}

/// The frame of a hinge line (its rows): x along it, y level and normal to it, z normal to
/// both, pointing up. Left-handed where the line runs towards +y, as in the reference, whose
/// y is (1, -x.x / x.y, 0) normalised: only the sign of x.y matters, so a hinge line of a fin
/// (x.y tiny, from rounding) has a frame, and one with x.y exactly 0 has none.
Matrix hingeFrame(const Vector& along) {
  const Vector x = along.normalized();
  const double level = x.x() * x.x() + x.y() * x.y();
  if (x.y() == 0.0 || level == 0.0)
    throw Error(ErrorCode::InvalidModel, "the hinge line runs parallel to the x-z plane; it has no hinge frame");
  Matrix frame;
  frame.row(0) = x;
  frame.row(1) = (x.y() > 0 ? 1.0 : -1.0) * Vector(x.y(), -x.x(), 0.0) / std::sqrt(level);
  frame.row(2) = Vector(-x.x() * x.z() / level, -x.y() * x.z() / level, 1.0).normalized();
  return frame;
}

}  // namespace

StepValues stepValuesAt(const schema::ControlSurfaceStepsType& steps, double controlParameter) {
  const auto& list = steps.step;
  if (list.empty()) return {};
  if (controlParameter <= list[0].controlParameter) return valuesOf(list[0]);
  for (std::size_t k = 0; k + 1 < list.size(); ++k) {
    const double from = list[k].controlParameter, to = list[k + 1].controlParameter;
    if (controlParameter >= from && controlParameter <= to) {
      const double share = to > from ? (controlParameter - from) / (to - from) : 1.0;
      return blend(valuesOf(list[k]), valuesOf(list[k + 1]), share);
    }
  }
  return valuesOf(list[list.size() - 1]);
}

gp_Trsf hingeMotion(const gp_Pnt& inner, const gp_Pnt& outer, const StepValues& values) {
  const Vector h1 = asVector(inner.XYZ()), h2 = asVector(outer.XYZ());
  const Vector moved1 = h1 + asVector(values.innerTranslation), moved2 = h2 + asVector(values.outerTranslation);
  const double length = (h2 - h1).norm(), movedLength = (moved2 - moved1).norm();
  if (length < 1e-12 || movedLength < 1e-12) throw Error(ErrorCode::InvalidModel, "the hinge line has no length");

  const Matrix frame = hingeFrame(h2 - h1);
  const Vector inFrame = frame * (moved2 - moved1);
  const double turn = std::atan2(inFrame.y(), inFrame.x());
  const double tilt = std::acos(std::clamp(inFrame.z() / movedLength, -1.0, 1.0));
  const Matrix rotation = frame.transpose() * rotationZ(turn) * rotationY(tilt - M_PI / 2.0) *
                          rotationX(-values.rotation * kDegree) * frame;
  // The moved hinge line is shorter or longer than at rest; the device keeps its middle.
  const Vector slide = -0.5 * (length - movedLength) * (moved2 - moved1) / movedLength;
  const Vector translation = moved1 + slide - rotation * h1;

  gp_Trsf motion;
  motion.SetValues(rotation(0, 0), rotation(0, 1), rotation(0, 2), translation.x(), rotation(1, 0), rotation(1, 1),
                   rotation(1, 2), translation.y(), rotation(2, 0), rotation(2, 1), rotation(2, 2), translation.z());
  return motion;
}

double rotationAngle(const gp_Trsf& motion) {
  const gp_Mat r = motion.VectorialPart();
  const gp_XYZ axis(r(3, 2) - r(2, 3), r(1, 3) - r(3, 1), r(2, 1) - r(1, 2));
  return std::atan2(0.5 * axis.Modulus(), 0.5 * (r(1, 1) + r(2, 2) + r(3, 3) - 1.0)) / kDegree;
}

}  // namespace airshape::controlsurfaces
