// Distances from points near a surface, as `airshape gordon --report` measures its inputs
// against the surface: the nearest grid samples (searched block by block) refined by Newton.
// (Points far off its edges get an upper bound; the report projects those exactly.)
#include <cmath>

#include <gtest/gtest.h>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>

#include "airshape/geometry/surface_projection.h"
#include "sheet_of_many_spans.h"

namespace airshape::geometry {
namespace {

/// A gently curved sheet over [0, 10] × [0, 1]: 40 × 4 cubic spans.
Handle(Geom_BSplineSurface) curvedSheet() {
  return test::sheetOfManySpans([](double x, double y) { return 0.3 * std::sin(0.6 * x) + 0.1 * y * y; });
}

TEST(SurfaceProjector, APointOffAlongTheNormalIsThatFarFromTheSurface) {
  const Handle(Geom_BSplineSurface) sheet = curvedSheet();
  const SurfaceProjector projector(sheet, 120);
  for (double u = 0.3; u < 40.0; u += 1.7)
    for (double v = 0.2; v < 4.0; v += 0.45) {
      GeomLProp_SLProps properties(sheet, u, v, 1, 1e-9);
      ASSERT_TRUE(properties.IsNormalDefined());
      for (double offset : {0.0, 1e-4, -0.02, 0.05}) {
        const gp_Pnt point = properties.Value().Translated(offset * gp_Vec(properties.Normal()));
        EXPECT_NEAR(projector.distance(point), std::abs(offset), 1e-10) << "u " << u << " v " << v;
      }
    }
}

}  // namespace
}  // namespace airshape::geometry
