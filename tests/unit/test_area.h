#pragma once
// The area of faces for the plugin's tests: OCCT's adaptive integration, to 1e-12.

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::test {

inline double accurateArea(const TopoDS_Shape& faces) {
  GProp_GProps properties;
  BRepGProp::SurfaceProperties(faces, properties, 1e-12);
  return properties.Mass();
}

}  // namespace airshape::test
