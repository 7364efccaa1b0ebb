#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "airshape/model/placement.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::rotor {

/// One rotor blade attachment of a rotor hub: which blade it carries, at which azimuths, on
/// which hinges (docs/rotor.md; QUERY-components §5).
class BladeAttachment {
 public:
  BladeAttachment(const Configuration& configuration, const schema::RotorType& rotor,
                  const schema::RotorBladeAttachmentType& attachment);

  const std::string& bladeUid() const { return attachment_.rotorBladeUID; }
  /// Where the attachment is defined, for errors.
  const std::string& xpath() const { return attachment_.xpath; }
  /// The azimuths of its blades in degrees: the `azimuthAngles` list, else n evenly spaced.
  const std::vector<double>& azimuths() const { return azimuths_; }

  /// What moves a blade from its own frame to its place on the rotor.
  struct Steps {
    bool hinges = true;             ///< turn it about its hinges (at their neutral positions)
    bool rotationDirection = true;  ///< mirror it (x → −x) for a negative rotation speed
    bool rotor = true;              ///< apply the rotor's transformation
  };
  /// The map of the blade at `azimuth` (degrees): its hinges, last first (each about its
  /// position: pitch about x, flap about y with the angle negated, lead-lag about z); the
  /// mirror for a negative rotation speed (which also negates the azimuth); the turn about z
  /// by the azimuth; the rotor's transformation.
  model::Transform bladeTransform(double azimuth, const Steps& steps) const;

  /// The rotor's transformation.
  const model::Transform& rotorTransform() const { return rotorTransform_; }

 private:
  const schema::RotorType& rotor_;
  const schema::RotorBladeAttachmentType& attachment_;
  model::Transform rotorTransform_;
  std::vector<double> azimuths_;
};

/// The blade attachments of a rotor, in document order.
std::vector<BladeAttachment> bladeAttachmentsOf(const Configuration& configuration, const schema::RotorType& rotor);

}  // namespace airshape::rotor
