// A loft of closed profiles built with shared edges (geometry/loft_shell.h) is a valid closed
// solid with the same volume and area as the same faces sewn, nose points included.
#include <cmath>

#include <gtest/gtest.h>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/loft_piece.h"
#include "airshape/geometry/loft_shell.h"
#include "airshape/geometry/skinning.h"
#include "airshape/geometry/surface_split.h"

namespace airshape::geometry {
namespace {

/// A loft through ellipses at x = 0, 1, 2, 3 with these half axes (0: a point).
Handle(Geom_BSplineSurface) ellipseLoft(const std::vector<double>& radii, std::vector<double>& sites) {
  constexpr int kPoints = 40;
  std::vector<double> parameters;
  for (int i = 0; i <= kPoints; ++i) parameters.push_back(static_cast<double>(i) / kPoints);
  std::vector<Handle(Geom_BSplineCurve)> profiles;
  for (std::size_t k = 0; k < radii.size(); ++k) {
    std::vector<gp_Pnt> points;
    for (int i = 0; i <= kPoints; ++i) {
      const double a = 2.0 * M_PI * i / kPoints;
      points.emplace_back(static_cast<double>(k), radii[k] * std::sin(a), 1.3 * radii[k] * std::cos(a));
    }
    points.back() = points.front();
    profiles.push_back(interpolateCurve(points, parameters, 3, true));
    sites.push_back(static_cast<double>(k) / static_cast<double>(radii.size() - 1));
  }
  return skinCurves(profiles, sites, skinningSpace(sites, 3, false));
}

/// The same faces sewn: the reference the shared-edge solid must match.
TopoDS_Shape sewnLoft(const Handle(Geom_BSplineSurface) & loft, const std::vector<double>& sites) {
  std::vector<TopoDS_Face> faces = {loftCap(loft, sites.front(), true), loftCap(loft, sites.back(), true)};
  for (std::size_t k = 0; k + 1 < sites.size(); ++k) faces.push_back(loftFace(loft, sites[k], sites[k + 1]));
  return sewnSolid(faces);
}

void expectSameSolidAsSewn(const std::vector<double>& radii) {
  std::vector<double> sites;
  const Handle(Geom_BSplineSurface) loft = ellipseLoft(radii, sites);
  std::vector<TopoDS_Face> faces;
  const TopoDS_Solid solid = closedLoftSolid(loft, sites, faces);
  EXPECT_TRUE(BRepCheck_Analyzer(solid).IsValid());
  ASSERT_EQ(faces.size(), sites.size() + 1);
  EXPECT_EQ(faces.front().IsNull(), radii.front() == 0.0);
  EXPECT_EQ(faces.back().IsNull(), radii.back() == 0.0);
  // Every profile edge bounds the two faces beside it: nothing is left open.
  TopTools_IndexedDataMapOfShapeListOfShape facesOfEdges;
  TopExp::MapShapesAndUniqueAncestors(solid, TopAbs_EDGE, TopAbs_FACE, facesOfEdges);
  for (int i = 1; i <= facesOfEdges.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(facesOfEdges.FindKey(i));
    if (BRep_Tool::Degenerated(edge) || facesOfEdges(i).Extent() == 2) continue;
    ASSERT_EQ(facesOfEdges(i).Extent(), 1);
    EXPECT_TRUE(BRep_Tool::IsClosed(edge, TopoDS::Face(facesOfEdges(i).First()))) << "an edge of one face is its seam";
  }
  const TopoDS_Shape sewn = sewnLoft(loft, sites);
  EXPECT_NEAR(volumeOf(solid), volumeOf(sewn), 1e-9 * volumeOf(sewn));
  EXPECT_NEAR(areaOf(solid), areaOf(sewn), 1e-9 * areaOf(sewn));
  EXPECT_GT(volumeOf(solid), 0.0);
}

TEST(LoftShell, AClosedLoftWithCapsIsTheSewnSolid) { expectSameSolidAsSewn({0.5, 1.0, 1.2, 0.8}); }

TEST(LoftShell, ANoseShrunkToAPointHasNoCap) { expectSameSolidAsSewn({0.0, 1.0, 1.2, 0.8}); }

TEST(LoftShell, StretchesOfDifferentSurfacesShareTheirProfiles) {
  // Two lofts that meet at the middle profile (a guided fuselage's rows of patches are such).
  std::vector<double> frontSites, rearSites;
  const auto front = ellipseLoft({0.5, 1.0}, frontSites), rear = ellipseLoft({1.0, 0.7}, rearSites);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(1.0, 0.0, 0.0));
  const auto moved = Handle(Geom_BSplineSurface)::DownCast(rear->Transformed(shift));
  std::vector<TopoDS_Face> faces;
  const TopoDS_Solid solid = closedLoftSolid({{front, 0.0, 1.0}, {moved, 0.0, 1.0}}, faces);
  EXPECT_TRUE(BRepCheck_Analyzer(solid).IsValid());
  const TopoDS_Shape sewn = sewnSolid(
      {loftFace(front, 0.0, 1.0), loftFace(moved, 0.0, 1.0), loftCap(front, 0.0, true), loftCap(moved, 1.0, true)});
  EXPECT_NEAR(volumeOf(solid), volumeOf(sewn), 1e-9 * volumeOf(sewn));
  // Stretches that do not meet are refused, so that the caller sews instead.
  EXPECT_THROW(closedLoftSolid({{front, 0.0, 1.0}, {rear, 0.0, 1.0}}, faces), Error);
}

TEST(SurfaceSplit, PartsAreTheSegmentsOfTheSurface) {
  // Sites between and on the loft's knots, the ends included; one site in the middle of a span.
  std::vector<double> sites;
  const Handle(Geom_BSplineSurface) loft = ellipseLoft({0.5, 1.0, 1.2, 0.8, 0.3}, sites);
  sites.insert(sites.begin() + 2, 0.5 * (sites[1] + sites[2]));
  const auto parts = splitAlongV(*loft, sites);
  ASSERT_EQ(parts.size(), sites.size() - 1);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    auto segment = Handle(Geom_BSplineSurface)::DownCast(loft->Copy());
    segment->Segment(0.0, 1.0, sites[k], sites[k + 1]);
    double u0, u1, v0, v1;
    parts[k]->Bounds(u0, u1, v0, v1);
    EXPECT_NEAR(v0, sites[k], 1e-15);
    EXPECT_NEAR(v1, sites[k + 1], 1e-15);
    EXPECT_EQ(parts[k]->NbVPoles(), segment->NbVPoles()) << "part " << k << " carries only its own poles";
    for (int i = 0; i <= 10; ++i)
      for (int j = 0; j <= 10; ++j) {
        const double u = u0 + (u1 - u0) * i / 10.0, v = v0 + (v1 - v0) * j / 10.0;
        EXPECT_LT(parts[k]->Value(u, v).Distance(loft->Value(u, v)), 1e-12);
      }
  }
}

}  // namespace
}  // namespace airshape::geometry
