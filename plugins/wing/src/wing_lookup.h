#pragma once

#include <string>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::wing {

/// The wing (or rotor blade) that a part of it (a segment, a component segment) lies in.
const schema::WingType& wingHolding(const Configuration& configuration, const std::string& partUid);

/// A wing's component segment by uID; throws Error when the wing has none of that uID.
const schema::ComponentSegmentType& componentSegmentNamed(const schema::WingType& wing, const std::string& uid);

}  // namespace airshape::wing
