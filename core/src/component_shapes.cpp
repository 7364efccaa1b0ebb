#include "airshape/component_shapes.h"

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/graph/component_graph.h"
#include "airshape/model/symmetry.h"

namespace airshape {

const NamedShape& ComponentShapes::namedShapeOf(const Configuration& configuration, const std::string& uid) const {
  if (uid.empty())
    throw Error(ErrorCode::InvalidModel, "the element has no uID (the schema requires one): nothing names it to build");
  const long index = configuration.components().find(uid);
  if (index < 0) throw Error(ErrorCode::InvalidArgument, "no geometric component with uID '" + uid + "'");
  const std::string& nodeType = configuration.components().components()[static_cast<std::size_t>(index)].nodeType;
  const auto builder = builders_.find(nodeType);
  if (builder == builders_.end()) throw noShapeBuilt(uid, nodeType, declined(nodeType));
  return *configuration.cache().obtain<NamedShape>(
      "shape:" + uid, [&] { return std::make_shared<const NamedShape>(builder->second(configuration, uid)); });
}

const NamedShape& ComponentShapes::mirroredShapeOf(const Configuration& configuration, const std::string& uid) const {
  const std::string plane = model::resolvedSymmetry(configuration, uid);
  if (plane == "none") throw Error(ErrorCode::InvalidArgument, "component '" + uid + "' has no symmetry plane");
  const NamedShape& original = namedShapeOf(configuration, uid);
  return *configuration.cache().obtain<NamedShape>("mirrored-shape:" + uid, [&] {
    return std::make_shared<const NamedShape>(transformedNamedShape(original, model::mirrorIn(plane), " (mirrored)"));
  });
}

Error noShapeBuilt(const std::string& uid, const std::string& nodeType, const std::string* declinedBecause) {
  if (nodeType == graph::kModelNodeType)
    return Error(ErrorCode::InvalidArgument, "'" + uid + "' is the model (type plane): it has no shape");
  if (declinedBecause != nullptr)
    return Error(ErrorCode::NotImplemented, "'" + uid + "' is not built: " + *declinedBecause);
  return Error(ErrorCode::NotImplemented, "no builder yet for " + nodeType);
}

}  // namespace airshape
