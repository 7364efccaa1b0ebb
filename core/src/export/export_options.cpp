#include "airshape/export/export_options.h"

#include "airshape/error.h"

namespace airshape::exporting {

double positiveNumber(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !(value > 0))
    throw Error(ErrorCode::InvalidArgument, option + ": '" + text + "' is not a positive number");
  return value;
}

std::vector<Pose> parsePoses(const std::string& list) {
  std::vector<Pose> poses;
  for (const std::string& item : splitAtCommas(list)) {
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      throw Error(ErrorCode::InvalidArgument, "--deflect: expected UID=P, got '" + item + "'");
    Pose pose{item.substr(0, equals), Pose::At::Parameter, 0.0};
    const std::string value = item.substr(equals + 1);
    if (value == "min" || value == "max") {
      pose.at = value == "min" ? Pose::At::Minimum : Pose::At::Maximum;
    } else {
      std::size_t used = 0;
      try {
        pose.parameter = std::stod(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != value.size())
        throw Error(ErrorCode::InvalidArgument,
                    "--deflect: '" + value + "' is not a control parameter (a number, min or max) in '" + item + "'");
      if (pose.uid == "all")
        throw Error(ErrorCode::InvalidArgument, "--deflect: all takes min or max, not '" + value + "'");
    }
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace airshape::exporting
