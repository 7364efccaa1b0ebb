#include <set>

#include <gtest/gtest.h>
#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include "airshape/fused_shape.h"
#include "airshape/geometry/brep_measures.h"

namespace {

/// A box with its six faces named "<prefix>/<i>".
airshape::NamedShape namedBox(const std::string& prefix, const gp_Pnt& corner, double dx, double dy, double dz) {
  airshape::NamedShape box{BRepPrimAPI_MakeBox(corner, dx, dy, dz).Shape(), {}};
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(box.shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i)
    box.faces.emplace_back(prefix + "/" + std::to_string(i), TopoDS::Face(faces(i)));
  return box;
}

}  // namespace

TEST(FusedShape, UnionKeepsTheNamesOfWhatRemains) {
  // A unit cube and a 1 x 0.5 x 0.5 bar pushed half-way into it: the bar's end face lies
  // inside the cube and disappears; the cube's face it pierces gets a hole and keeps its
  // name, as do the bar's side faces, cut to what lies outside.
  const airshape::NamedShape a = namedBox("a", gp_Pnt(0, 0, 0), 1.0, 1.0, 1.0);
  const airshape::NamedShape b = namedBox("b", gp_Pnt(0.5, 0.25, 0.25), 1.0, 0.5, 0.5);
  const airshape::NamedShape fused = airshape::fuseNamedShapes({&a, &b});
  EXPECT_NEAR(airshape::geometry::volumeOf(fused.shape), 1.0 + 0.25 - 0.125, 1e-12);
  TopTools_IndexedMapOfShape resultFaces;
  TopExp::MapShapes(fused.shape, TopAbs_FACE, resultFaces);
  EXPECT_EQ(static_cast<int>(fused.faces.size()), resultFaces.Extent());  // every face named once
  std::set<std::string> names;
  for (const auto& [name, face] : fused.faces) {
    EXPECT_TRUE(resultFaces.Contains(face)) << name;
    names.insert(name);
  }
  EXPECT_EQ(names.size(), 11u);  // 12 faces less the bar's end inside the cube
  EXPECT_EQ(fused.faces.size(), 11u);
}

TEST(FusedShape, OneShapeIsItself) {
  const airshape::NamedShape a = namedBox("a", gp_Pnt(0, 0, 0), 2.0, 2.0, 2.0);
  EXPECT_TRUE(airshape::fuseNamedShapes({&a}).shape.IsSame(a.shape));
}
