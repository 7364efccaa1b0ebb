#pragma once

#include <vector>

#include "airshape/named_shape.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "airshape/wing/wing_services.h"
#include "blade_attachment.h"

namespace airshape::rotor {

/// A rotor's figures and shape, as QUERY-components §5 defines them (docs/rotor.md): its blades
/// are the rotor-blade wings its hub attaches, each placed by BladeAttachment::bladeTransform.
class RotorGeometry {
 public:
  RotorGeometry(const Configuration& configuration, const wing::WingServices& wing, const schema::RotorType& rotor);

  /// Blades over all attachments.
  std::size_t bladeCount() const;
  /// The largest distance from the rotor axis of a quarter-chord point at a section of the
  /// first blade of any attachment, placed by the rotor's transformation only.
  double radius() const;
  /// Σ over attachments of blades × planform area of one blade: its segments' chord
  /// quadrilaterals in the blade's frame, flattened to z = 0, placed by the rotor.
  double totalBladePlanformArea() const;
  /// Nominal rpm / 30 · π · radius (0 without a nominal rotation speed).
  double tipSpeed() const;
  /// The compound of all attached blades, their faces named as the blade's, plus " (blade k)".
  NamedShape shape() const;

 private:
  double bladeRadius(const BladeAttachment& attachment) const;
  double bladePlanformArea(const BladeAttachment& attachment) const;

  const Configuration& configuration_;
  const wing::WingServices& wing_;
  const schema::RotorType& rotor_;
  std::vector<BladeAttachment> attachments_;
};

}  // namespace airshape::rotor
