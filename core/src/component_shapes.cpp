#include "airshape/component_shapes.h"

#include <BRepBuilderAPI_Transform.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/symmetry.h"

namespace airshape {

const NamedShape& ComponentShapes::namedShapeOf(const Configuration& configuration, const std::string& uid) const {
  const long index = configuration.components().find(uid);
  if (index < 0) throw Error(ErrorCode::InvalidArgument, "no geometric component with uID '" + uid + "'");
  const std::string& nodeType = configuration.components().components()[static_cast<std::size_t>(index)].nodeType;
  const auto builder = builders_.find(nodeType);
  if (builder == builders_.end()) throw Error(ErrorCode::NotImplemented, "no builder yet for " + nodeType);
  return *configuration.cache().obtain<NamedShape>(
      "shape:" + uid, [&] { return std::make_shared<const NamedShape>(builder->second(configuration, uid)); });
}

const NamedShape& ComponentShapes::mirroredShapeOf(const Configuration& configuration, const std::string& uid) const {
  const std::string plane = model::resolvedSymmetry(configuration, uid);
  if (plane == "none") throw Error(ErrorCode::InvalidArgument, "component '" + uid + "' has no symmetry plane");
  const NamedShape& original = namedShapeOf(configuration, uid);
  return *configuration.cache().obtain<NamedShape>("mirrored-shape:" + uid, [&] {
    const gp_Dir normal = plane == "x-y" ? gp_Dir(0, 0, 1) : plane == "x-z" ? gp_Dir(0, 1, 0) : gp_Dir(1, 0, 0);
    gp_Trsf mirror;
    mirror.SetMirror(gp_Ax2(gp_Pnt(0, 0, 0), normal));
    BRepBuilderAPI_Transform transform(original.shape, mirror, true);
    auto mirrored = std::make_shared<NamedShape>();
    mirrored->shape = transform.Shape();
    for (const auto& [name, face] : original.faces)
      mirrored->faces.emplace_back(name + " (mirrored)", TopoDS::Face(transform.ModifiedShape(face)));
    return std::shared_ptr<const NamedShape>(mirrored);
  });
}

}  // namespace airshape
