#pragma once

#include <vector>

#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "airshape/named_shape.h"

namespace airshape::structure {

/// Shapes gathered into one compound (the form OCCT's Boolean operations take a list in).
template <class Shapes>
TopoDS_Compound compoundOf(const Shapes& shapes) {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const auto& shape : shapes) builder.Add(compound, shape);
  return compound;
}

/// The edges of a shape gathered into one shape: a structure element that is lines (a frame, a
/// stringer, a beam's axis), without faces or names.
inline NamedShape edgesOf(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Shape> edges;
  for (TopExp_Explorer edge(shape, TopAbs_EDGE); edge.More(); edge.Next()) edges.push_back(edge.Current());
  NamedShape lines;
  lines.shape = compoundOf(edges);
  return lines;
}

}  // namespace airshape::structure
