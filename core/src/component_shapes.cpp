#include "airshape/component_shapes.h"

#include <algorithm>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/fused_shape.h"
#include "airshape/graph/component_graph.h"
#include "airshape/model/symmetry.h"

namespace airshape {

const NamedShape& ComponentShapes::cleanNamedShapeOf(const Configuration& configuration, const std::string& uid) const {
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

const NamedShape& ComponentShapes::namedShapeOf(const Configuration& configuration, const std::string& uid) const {
  const NamedShape& clean = cleanNamedShapeOf(configuration, uid);
  if (!anyCutOutsOn(configuration)) return clean;
  // The cut depends on the cutters too (a cutter edited elsewhere): kept for the whole model,
  // which any edit forgets.
  return *configuration.cache().obtainForWholeModel<NamedShape>("with cut-outs of others " + uid, [&] {
    std::vector<NamedShape> tools;
    for (const ComponentCutOuts& cutOuts : cutOuts_)
      if (configuration.option(cutOuts.option))
        for (NamedShape& tool : cutOuts.tools(configuration, uid)) tools.push_back(std::move(tool));
    if (tools.empty()) return std::make_shared<const NamedShape>(clean);
    std::vector<const NamedShape*> parts;
    for (const NamedShape& tool : tools) parts.push_back(&tool);
    try {
      return std::make_shared<const NamedShape>(cutNamedShape(clean, fuseNamedShapes(parts)));
    } catch (const Error& error) {
      throw Error(ErrorCode::InvalidModel,
                  "the cut-outs of other components could not be cut out of '" + uid + "' (" + error.what() + ")");
    }
  });
}

bool ComponentShapes::isCutByOthers(const Configuration& configuration, const std::string& uid) const {
  if (!anyCutOutsOn(configuration)) return false;
  return !namedShapeOf(configuration, uid).shape.IsSame(cleanNamedShapeOf(configuration, uid).shape);
}

bool ComponentShapes::anyCutOutsOn(const Configuration& configuration) const {
  return std::any_of(cutOuts_.begin(), cutOuts_.end(),
                     [&](const ComponentCutOuts& cutOuts) { return configuration.option(cutOuts.option); });
}

const NamedShape& ComponentShapes::mirroredShapeOf(const Configuration& configuration, const std::string& uid) const {
  const std::string plane = model::resolvedSymmetry(configuration, uid);
  if (plane == "none") throw Error(ErrorCode::InvalidArgument, "component '" + uid + "' has no symmetry plane");
  const NamedShape& original = namedShapeOf(configuration, uid);
  const auto mirrored = [&] {
    return std::make_shared<const NamedShape>(transformedNamedShape(original, model::mirrorIn(plane), " (mirrored)"));
  };
  // A half with cut-outs of others depends on them as the half itself does.
  if (isCutByOthers(configuration, uid))
    return *configuration.cache().obtainForWholeModel<NamedShape>("mirrored with cut-outs of others " + uid, mirrored);
  return *configuration.cache().obtain<NamedShape>("mirrored-shape:" + uid, mirrored);
}

Error noShapeBuilt(const std::string& uid, const std::string& nodeType, const std::string* declinedBecause) {
  if (nodeType == graph::kModelNodeType)
    return Error(ErrorCode::InvalidArgument, "'" + uid + "' is the model (type plane): it has no shape");
  if (declinedBecause != nullptr)
    return Error(ErrorCode::NotImplemented, "'" + uid + "' is not built: " + *declinedBecause);
  return Error(ErrorCode::NotImplemented, "no builder yet for " + nodeType);
}

}  // namespace airshape
