#include "airshape/meshing/mesh_options.h"

#include "airshape/error.h"

namespace airshape::meshing {

namespace {

/// --size SIZE (every surface) or --size UID=SIZE[,UID=SIZE...] (those components' surfaces).
void parseSize(const std::string& text, MeshOptions& options) {
  if (text.find('=') == std::string::npos) {
    options.size = exporting::positiveNumber(text, "--size");
    return;
  }
  for (const auto& [uid, size] : parseComponentSizes(text)) options.componentSizes[uid] = size;
}

/// Takes one option (and its value) at `arguments[i]` into `options`; false when it is none
/// of the mesh's.
bool takeOption(const std::vector<std::string>& arguments, std::size_t& i, MeshOptions& options) {
  const std::string& argument = arguments[i];
  const auto value = [&]() -> const std::string& {
    if (i + 1 >= arguments.size()) throw Error(ErrorCode::InvalidArgument, argument + ": a value must follow");
    return arguments[++i];
  };
  if (argument == "--components") {
    options.scene.components = exporting::splitAtCommas(value());
  } else if (argument == "--deflect") {
    const std::vector<exporting::Pose> poses = exporting::parsePoses(value());
    options.scene.poses.insert(options.scene.poses.end(), poses.begin(), poses.end());
  } else if (argument == "--mirror") {
    options.scene.mirror = true;
  } else if (argument == "--size") {
    parseSize(value(), options);
  } else if (argument == "--min-size") {
    options.minSize = exporting::positiveNumber(value(), "--min-size");
  } else if (argument == "--curvature") {
    options.elementsPerCircle = exporting::positiveNumber(value(), "--curvature");
  } else if (argument == "--farfield") {
    options.farfield = parseFarfield(value());
  } else if (argument == "--boundary-layer") {
    options.boundaryLayer = parseBoundaryLayer(value());
  } else if (argument == "--symmetry") {
    options.symmetry = true;
  } else if (argument == "--structure") {
    options.scene.structure = true;
  } else if (argument == "--order") {
    options.order = static_cast<int>(exporting::positiveNumber(value(), "--order"));
  } else {
    return false;
  }
  return true;
}

}  // namespace

MeshOptions takeMeshOptions(std::vector<std::string>& arguments) {
  MeshOptions options;
  std::vector<std::string> rest;
  for (std::size_t i = 0; i < arguments.size(); ++i)
    if (!takeOption(arguments, i, options)) rest.push_back(arguments[i]);
  arguments = rest;
  return options;
}

double BoundaryLayer::thickness() const {
  double height = firstHeight, sum = 0;
  for (int layer = 0; layer < count; ++layer, height *= growth) sum += height;
  return sum;
}

BoundaryLayer parseBoundaryLayer(const std::string& text) {
  const std::vector<std::string> parts = exporting::splitAtCommas(text);
  if (parts.size() != 2 && parts.size() != 3)
    throw Error(ErrorCode::InvalidArgument,
                "--boundary-layer: expected COUNT,FIRST_HEIGHT[,GROWTH], got '" + text + "'");
  BoundaryLayer layer;
  const double count = exporting::positiveNumber(parts[0], "--boundary-layer COUNT");
  if (count != static_cast<int>(count) || count > 100)
    throw Error(ErrorCode::InvalidArgument, "--boundary-layer: COUNT is a whole number up to 100, not " + parts[0]);
  layer.count = static_cast<int>(count);
  layer.firstHeight = exporting::positiveNumber(parts[1], "--boundary-layer FIRST_HEIGHT");
  if (parts.size() == 3) layer.growth = exporting::positiveNumber(parts[2], "--boundary-layer GROWTH");
  if (layer.growth < 1)
    throw Error(ErrorCode::InvalidArgument, "--boundary-layer: GROWTH is at least 1, not " + parts[2]);
  return layer;
}

std::map<std::string, double> parseComponentSizes(const std::string& list) {
  std::map<std::string, double> sizes;
  for (const std::string& item : exporting::splitAtCommas(list)) {
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      throw Error(ErrorCode::InvalidArgument, "--size: expected SIZE or UID=SIZE, got '" + item + "'");
    sizes[item.substr(0, equals)] =
        exporting::positiveNumber(item.substr(equals + 1), "--size " + item.substr(0, equals));
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
    farfield.lengths = exporting::positiveNumber(distance.substr(0, distance.size() - 1), "--farfield");
  } else {
    farfield.metres = exporting::positiveNumber(distance, "--farfield");
  }
  return farfield;
}

}  // namespace airshape::meshing
