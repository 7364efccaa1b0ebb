#pragma once

#include <string>
#include <vector>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// Where a spar runs through, as the schema gives it (`sparPosition`).
struct SparPosition {
  enum class Kind { EtaXsi, OnRib, OnCurve };
  std::string uid;
  std::string xpath;
  Kind kind = Kind::EtaXsi;
  double eta = 0.0, xsi = 0.0;
  /// EtaXsi: the component segment or a wing segment of its wing; OnCurve: the line (a spar
  /// segment, the leading or the trailing edge) whose length eta is a share of
  std::string referenceUid;
  std::string ribsUid;  ///< OnRib: the ribs definition, and the rib's number in it (from 1)
  long long ribNumber = 1;
};

/// One spar segment: the spar positions it runs through, in order, and where it lies.
struct SparSegment {
  std::string uid;
  std::string xpath;
  std::string componentSegmentUid;
  std::string wingUid;
  std::vector<SparPosition> positions;
  std::string deviceUid;  ///< the control device whose own structure it is, if any
};

/// A spar position as the schema gives it (or as older files do, with a warning), read.
SparPosition sparPositionOf(const Configuration& configuration, const schema::SparPositionType& node);

/// The spar segment with this uID in any model. Throws Error when none has it, naming the
/// CPACS path when one of its spar position uIDs names no spar position.
SparSegment sparSegmentNamed(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::structure
