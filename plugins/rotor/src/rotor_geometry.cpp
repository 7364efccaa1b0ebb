#include "rotor_geometry.h"

#include <algorithm>
#include <cmath>

#include <BRep_Builder.hxx>
#include <Eigen/Geometry>
#include <TopoDS_Compound.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"

namespace airshape::rotor {

namespace {

using Surface = wing::WingServices::Surface;

Eigen::Vector3d vectorOf(const gp_Pnt& p) { return Eigen::Vector3d(p.X(), p.Y(), p.Z()); }

}  // namespace

RotorGeometry::RotorGeometry(const Configuration& configuration, const wing::WingServices& wing,
                             const schema::RotorType& rotor)
    : configuration_(configuration),
      wing_(wing),
      rotor_(rotor),
      attachments_(bladeAttachmentsOf(configuration, rotor)) {
  for (const BladeAttachment& attachment : attachments_) {
    try {
      wing_.segmentUids(configuration_, attachment.bladeUid());
    } catch (const Error&) {
      throw Error(ErrorCode::InvalidModel, "rotorBladeUID '" + attachment.bladeUid() + "' names no rotor blade", {},
                  attachment.xpath() + "/rotorBladeUID");
    }
  }
}

std::size_t RotorGeometry::bladeCount() const {
  std::size_t count = 0;
  for (const BladeAttachment& attachment : attachments_) count += attachment.azimuths().size();
  return count;
}

double RotorGeometry::bladeRadius(const BladeAttachment& attachment) const {
  const model::Transform& rotor = attachment.rotorTransform();
  const Eigen::Vector3d origin = rotor * Eigen::Vector3d::Zero();
  const Eigen::Vector3d axis = (rotor * Eigen::Vector3d::UnitZ() - origin).normalized();
  auto distance = [&](std::size_t segment, double eta) {
    const Eigen::Vector3d p =
        rotor * vectorOf(wing_.segmentPoint(configuration_, attachment.bladeUid(), segment, eta, 0.25, Surface::Chord));
    const Eigen::Vector3d offset = p - origin;
    return (offset - offset.dot(axis) * axis).norm();
  };
  const std::size_t segments = wing_.segmentUids(configuration_, attachment.bladeUid()).size();
  if (segments == 0) return 0.0;
  double radius = distance(0, 0.0);
  for (std::size_t s = 0; s < segments; ++s) radius = std::max(radius, distance(s, 1.0));
  return radius;
}

double RotorGeometry::radius() const {
  double radius = 0.0;
  for (const BladeAttachment& attachment : attachments_)
    if (!attachment.azimuths().empty()) radius = std::max(radius, bladeRadius(attachment));
  return radius;
}

double RotorGeometry::bladePlanformArea(const BladeAttachment& attachment) const {
  const std::size_t segments = wing_.segmentUids(configuration_, attachment.bladeUid()).size();
  auto corner = [&](std::size_t s, double eta, double xsi) {
    Eigen::Vector3d p =
        vectorOf(wing_.segmentPoint(configuration_, attachment.bladeUid(), s, eta, xsi, Surface::Chord));
    p.z() = 0.0;
    return Eigen::Vector3d(attachment.rotorTransform() * p);
  };
  double area = 0.0;
  for (std::size_t s = 0; s < segments; ++s) {
    const Eigen::Vector3d a = corner(s, 1, 0), b = corner(s, 1, 1), c = corner(s, 0, 1), d = corner(s, 0, 0);
    area += 0.5 * (c - a).cross(d - b).norm();
  }
  return area;
}

double RotorGeometry::totalBladePlanformArea() const {
  double area = 0.0;
  for (const BladeAttachment& attachment : attachments_)
    if (!attachment.azimuths().empty())
      area += static_cast<double>(attachment.azimuths().size()) * bladePlanformArea(attachment);
  return area;
}

double RotorGeometry::tipSpeed() const {
  return rotor_.nominalRotationsPerMinute.value_or(0.0) / 30.0 * M_PI * radius();
}

NamedShape RotorGeometry::shape() const {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  NamedShape result;
  std::size_t index = 0;
  for (const BladeAttachment& attachment : attachments_) {
    if (attachment.azimuths().empty()) continue;
    const NamedShape& blade = configuration_.shapes().namedShapeOf(configuration_, attachment.bladeUid());
    for (const double azimuth : attachment.azimuths()) {
      const NamedShape placed = transformedNamedShape(blade, attachment.bladeTransform(azimuth, {}),
                                                      " (blade " + std::to_string(++index) + ")");
      builder.Add(compound, placed.shape);
      result.faces.insert(result.faces.end(), placed.faces.begin(), placed.faces.end());
    }
  }
  if (index == 0) throw Error(ErrorCode::InvalidModel, "the rotor attaches no blades", {}, rotor_.xpath);
  result.shape = compound;
  return result;
}

}  // namespace airshape::rotor
