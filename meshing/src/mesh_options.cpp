#include "airshape/meshing/mesh_options.h"

#include "airshape/error.h"

namespace airshape::meshing {

namespace {

/// A positive number, the whole text; throws naming `option` otherwise.
double positive(const std::string& text, const std::string& option) {
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

}  // namespace

std::map<std::string, double> parseComponentSizes(const std::string& list) {
  std::map<std::string, double> sizes;
  for (const std::string& item : exporting::splitAtCommas(list)) {
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      throw Error(ErrorCode::InvalidArgument, "--size: expected SIZE or UID=SIZE, got '" + item + "'");
    sizes[item.substr(0, equals)] = positive(item.substr(equals + 1), "--size " + item.substr(0, equals));
  }
  return sizes;
}

Farfield parseFarfield(const std::string& text) {
  Farfield farfield;
  std::string distance = text;
  if (const std::size_t colon = text.find(':'); colon != std::string::npos) {
    const std::string shape = text.substr(0, colon);
    if (shape == "sphere") {
      farfield.shape = Farfield::Shape::Sphere;
    } else if (shape != "box") {
      throw Error(ErrorCode::InvalidArgument, "--farfield: the shape is box or sphere, not '" + shape + "'");
    }
    distance = text.substr(colon + 1);
  }
  if (!distance.empty() && (distance.back() == 'L' || distance.back() == 'l')) {
    farfield.lengths = positive(distance.substr(0, distance.size() - 1), "--farfield");
  } else {
    farfield.metres = positive(distance, "--farfield");
  }
  return farfield;
}

}  // namespace airshape::meshing
