#include "blade_attachment.h"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "airshape/configuration.h"
#include "airshape/error.h"

namespace airshape::rotor {

namespace {

constexpr double kDegree = M_PI / 180.0;

constexpr long long kMostBlades = 1000;

/// The azimuths of an attachment: its `azimuthAngles` list, else `numberOfBlades` evenly spaced.
std::vector<double> azimuthsOf(const schema::RotorBladeAttachmentType& attachment) {
  std::vector<double> azimuths;
  if (attachment.azimuthAngles) {
    std::stringstream list(*attachment.azimuthAngles);
    std::string item;
    while (std::getline(list, item, ';')) {
      if (item.find_first_not_of(" \t\r\n") == std::string::npos) continue;
      double azimuth = 0.0;
      try {
        azimuth = std::stod(item);
      } catch (const std::exception&) {
        throw Error(ErrorCode::InvalidModel, "azimuth angle '" + item + "' is not a number", {},
                    attachment.xpath + "/azimuthAngles");
      }
      azimuths.push_back(model::finite(azimuth, attachment.xpath + "/azimuthAngles"));
    }
    return azimuths;
  }
  const long long count = attachment.numberOfBlades.value_or(0);
  if (count < 0)
    throw Error(ErrorCode::InvalidModel, "a negative number of blades", {}, attachment.xpath + "/numberOfBlades");
  // No rotor or fan has so many; more would only fill the memory with blades.
  if (count > kMostBlades)
    throw Error(ErrorCode::InvalidModel,
                std::to_string(count) + " blades, more than " + std::to_string(kMostBlades) + "; refused", {},
                attachment.xpath + "/numberOfBlades");
  for (long long i = 0; i < count; ++i) azimuths.push_back(360.0 * static_cast<double>(i) / static_cast<double>(count));
  return azimuths;
}

}  // namespace

BladeAttachment::BladeAttachment(const Configuration& configuration, const schema::RotorType& rotor,
                                 const schema::RotorBladeAttachmentType& attachment)
    : rotor_(rotor),
      attachment_(attachment),
      rotorTransform_(model::componentTransform(configuration, rotor.uID)),
      azimuths_(azimuthsOf(attachment)) {}

model::Transform BladeAttachment::bladeTransform(double azimuth, const Steps& steps) const {
  model::Transform result = model::Transform::Identity();
  if (steps.hinges && attachment_.hinges) {
    const auto& hinges = attachment_.hinges->hinge;
    for (std::size_t k = hinges.size(); k-- > 0;) {
      const schema::RotorHubHingeType& hinge = hinges[k];
      const Eigen::Vector3d position = model::transformationMatrix(hinge.transformation.get()).translation();
      const double angle = hinge.neutralPosition.value_or(0.0) * kDegree;
      Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
      double turn = angle;
      if (hinge.type == schema::RotorHubHingeTypeType::Pitch) axis = Eigen::Vector3d::UnitX();
      if (hinge.type == schema::RotorHubHingeTypeType::Flap) axis = Eigen::Vector3d::UnitY(), turn = -angle;
      const model::Transform about =
          Eigen::Translation3d(position) * Eigen::AngleAxisd(turn, axis) * Eigen::Translation3d(-position);
      result = about * result;
    }
  }
  if (steps.rotationDirection && rotor_.nominalRotationsPerMinute.value_or(0.0) < 0.0) {
    result = Eigen::Scaling(-1.0, 1.0, 1.0) * result;
    azimuth = -azimuth;
  }
  result = Eigen::AngleAxisd(azimuth * kDegree, Eigen::Vector3d::UnitZ()) * result;
  if (steps.rotor) result = rotorTransform_ * result;
  return result;
}

std::vector<BladeAttachment> bladeAttachmentsOf(const Configuration& configuration, const schema::RotorType& rotor) {
  std::vector<BladeAttachment> attachments;
  if (rotor.rotorHub && rotor.rotorHub->rotorBladeAttachments)
    for (const auto& attachment : rotor.rotorHub->rotorBladeAttachments->rotorBladeAttachment)
      attachments.emplace_back(configuration, rotor, attachment);
  return attachments;
}

}  // namespace airshape::rotor
