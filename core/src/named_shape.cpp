#include "airshape/named_shape.h"

#include <cmath>

#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Builder.hxx>
#include <Eigen/Geometry>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_GTrsf.hxx>
#include <gp_Trsf.hxx>

#include "airshape/geometry/brep_building.h"

namespace airshape {

NamedShape sewnNamedSolid(const std::vector<std::pair<std::string, TopoDS_Face>>& namedFaces,
                          geometry::Orienting orienting) {
  std::vector<TopoDS_Face> faces, sewn;
  for (const auto& entry : namedFaces) faces.push_back(entry.second);
  NamedShape result;
  result.shape = geometry::sewnSolid(faces, &sewn, geometry::kJoinTolerance, orienting);
  for (std::size_t i = 0; i < namedFaces.size(); ++i)
    if (!sewn[i].IsNull()) result.faces.emplace_back(namedFaces[i].first, sewn[i]);
  return result;
}

NamedShape namedBooleanResult(BRepAlgoAPI_BuilderAlgo& operation, const std::vector<const NamedShape*>& inputs) {
  NamedShape result{operation.Shape(), {}};
  TopTools_IndexedMapOfShape resultFaces;
  TopExp::MapShapes(result.shape, TopAbs_FACE, resultFaces);
  for (const NamedShape* input : inputs)
    for (const auto& [name, face] : input->faces) {
      if (operation.IsDeleted(face)) continue;
      const TopTools_ListOfShape& pieces = operation.Modified(face);
      if (pieces.IsEmpty()) {
        if (resultFaces.Contains(face)) result.faces.emplace_back(name, face);
        continue;
      }
      for (const TopoDS_Shape& piece : pieces)
        if (resultFaces.Contains(piece)) result.faces.emplace_back(name, TopoDS::Face(piece));
    }
  return result;
}

NamedShape compoundOfNamedShapes(const std::vector<const NamedShape*>& shapes) {
  if (shapes.size() == 1) return *shapes.front();
  NamedShape all;
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  for (const NamedShape* part : shapes) {
    builder.Add(compound, part->shape);
    all.faces.insert(all.faces.end(), part->faces.begin(), part->faces.end());
  }
  all.shape = compound;
  return all;
}

NamedShape transformedNamedShape(const NamedShape& shape, const gp_Trsf& transformation, const std::string& suffix) {
  // Transformed copies: a shape moved by a location only loses its face names on the way
  // through a later copy (exports copy what they mesh).
  BRepBuilderAPI_Transform transform(shape.shape, transformation, true);
  NamedShape transformed{transform.Shape(), {}};
  for (const auto& [name, face] : shape.faces)
    transformed.faces.emplace_back(name + suffix, TopoDS::Face(transform.ModifiedShape(face)));
  return transformed;
}

NamedShape transformedNamedShape(const NamedShape& shape, const geometry::Affine3& transformation,
                                 const std::string& suffix) {
  const Eigen::Matrix3d linear = transformation.linear();
  const Eigen::Vector3d move = transformation.translation();
  const double scale = std::cbrt(linear.determinant());
  const bool similarity =
      scale != 0.0 &&
      (linear.transpose() * linear - scale * scale * Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-12;
  if (similarity) {
    gp_Trsf trsf;
    trsf.SetValues(linear(0, 0), linear(0, 1), linear(0, 2), move.x(), linear(1, 0), linear(1, 1), linear(1, 2),
                   move.y(), linear(2, 0), linear(2, 1), linear(2, 2), move.z());
    return transformedNamedShape(shape, trsf, suffix);
  }
  gp_GTrsf gtrsf;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) gtrsf.SetValue(r + 1, c + 1, linear(r, c));
    gtrsf.SetValue(r + 1, 4, move(r));
  }
  BRepBuilderAPI_GTransform transform(shape.shape, gtrsf, true);
  NamedShape transformed{transform.Shape(), {}};
  for (const auto& [name, face] : shape.faces)
    transformed.faces.emplace_back(name + suffix, TopoDS::Face(transform.ModifiedShape(face)));
  return transformed;
}

}  // namespace airshape
