#pragma once

#include <string>
#include <vector>

#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/named_shape.h"

namespace airshape::structure {

/// Faces gathered under names into one compound: the shape of a structure element.
class NamedFaces {
 public:
  NamedFaces() { builder_.MakeCompound(compound_); }

  void add(const std::string& name, const std::vector<TopoDS_Face>& faces) {
    for (const TopoDS_Face& face : faces) {
      builder_.Add(compound_, face);
      shape_.faces.emplace_back(name, face);
    }
  }
  bool empty() const { return shape_.faces.empty(); }
  NamedShape shape() const {
    NamedShape shape = shape_;
    shape.shape = compound_;
    return shape;
  }

 private:
  BRep_Builder builder_;
  TopoDS_Compound compound_;
  NamedShape shape_;
};

}  // namespace airshape::structure
