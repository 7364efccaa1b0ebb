#include "cowl_loft.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepFill.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <Geom_Circle.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/skinning.h"
#include "airshape/named_shape.h"
#include "cowl_parts.h"

namespace airshape::nacelle {

namespace {

constexpr double kDegree = M_PI / 180.0;
/// Samples along the profile per unit of zeta, and across each sector between two sections.
constexpr int kZetaSamples = 20;
constexpr int kSectorSamples = 8;

/// A point in the nacelle's cylindrical coordinates.
struct Cylindrical {
  double x, r;
};

Cylindrical cylindrical(const gp_Pnt& p) { return {p.X(), std::hypot(p.Y(), p.Z())}; }
gp_Pnt cartesian(double x, double r, double degrees) {
  return gp_Pnt(x, -r * std::sin(degrees * kDegree), r * std::cos(degrees * kDegree));
}

/// The zetas of one stretch of the outline, from `from` to `to`, evenly spaced.
std::vector<double> zetasBetween(double from, double to) {
  const int count = std::max(4, static_cast<int>(std::ceil(std::abs(to - from) * kZetaSamples)));
  std::vector<double> zetas;
  for (int i = 0; i <= count; ++i) zetas.push_back(from + (to - from) * i / count);
  return zetas;
}

/// A section's outline at a stretch's zetas, in cylindrical coordinates.
using Samples = std::vector<Cylindrical>;

Samples sampled(const PlacedProfile& section, const std::vector<double>& zetas) {
  Samples samples;
  for (double zeta : zetas) samples.push_back(cylindrical(section.at(zeta)));
  return samples;
}

/// The surface through a stretch of the outline swept from section a (samples atA) to section b.
TopoDS_Face sectorFace(const Samples& atA, const Samples& atB, double angleA, double angleB) {
  std::vector<std::vector<gp_Pnt>> grid;
  std::vector<double> across;
  for (int j = 0; j <= kSectorSamples; ++j) {
    const double u = static_cast<double>(j) / kSectorSamples, step = u * u * (3.0 - 2.0 * u);
    const double angle = angleA + u * (angleB - angleA);
    across.push_back(u);
    grid.emplace_back();
    for (std::size_t l = 0; l < atA.size(); ++l)
      grid.back().push_back(
          cartesian(atA[l].x + step * (atB[l].x - atA[l].x), atA[l].r + step * (atB[l].r - atA[l].r), angle));
  }
  // Evenly spaced zetas, evenly spaced parameters (also for the trailing edge's two ends).
  std::vector<double> along;
  for (std::size_t l = 0; l < atA.size(); ++l) along.push_back(static_cast<double>(l) / (atA.size() - 1));
  const Handle(Geom_BSplineSurface) surface = geometry::interpolateGrid(
      grid, along, geometry::skinningSpace(along, 3, false), across, geometry::skinningSpace(across, 3, false));
  return BRepBuilderAPI_MakeFace(surface, Precision::Confusion()).Face();
}

/// The arc of radius r about the x axis at axial position x from one angle to another.
Handle(Geom_Curve) arc(double x, double r, double from, double to) {
  const gp_Ax2 axes(gp_Pnt(x, 0, 0), gp_Dir(1, 0, 0), gp_Dir(0, 0, 1));
  return new Geom_TrimmedCurve(new Geom_Circle(axes, r), from * kDegree, to * kDegree);
}

/// The ruled face between an outline point's path across a sector and an arc of the inner side.
TopoDS_Face blendingFace(const Cylindrical& pa, const Cylindrical& pb, double angleA, double angleB,
                         const gp_Pnt& innerEnd) {
  // The outline point's path: the sector's motion of that one point, sampled and interpolated.
  std::vector<gp_Pnt> points;
  std::vector<double> parameters;
  for (int j = 0; j <= kSectorSamples; ++j) {
    const double u = static_cast<double>(j) / kSectorSamples, step = u * u * (3.0 - 2.0 * u);
    points.push_back(
        cartesian(pa.x + step * (pb.x - pa.x), pa.r + step * (pb.r - pa.r), angleA + u * (angleB - angleA)));
    parameters.push_back(u);
  }
  const Cylindrical inner = cylindrical(innerEnd);
  const TopoDS_Edge outerEdge = BRepBuilderAPI_MakeEdge(geometry::interpolateCurve(points, parameters, 3));
  const TopoDS_Edge innerEdge = BRepBuilderAPI_MakeEdge(arc(inner.x, inner.r, angleA, angleB));
  return BRepFill::Face(outerEdge, innerEdge);
}

}  // namespace

TopoDS_Shape loftedCowl(const Configuration& configuration, const schema::NacelleCowlType& cowl) {
  const schema::RotationCurveType& rotation = *cowl.rotationCurve;
  const Handle(Geom_BSplineCurve) inner = rotationPiece(configuration, cowl);
  std::vector<PlacedProfile> sections;
  for (const auto& section : cowl.sections->section) sections.push_back(placedProfile(configuration, section));
  for (PlacedProfile& section : sections) section.angle = std::fmod(std::fmod(section.angle, 360.0) + 360.0, 360.0);
  std::sort(sections.begin(), sections.end(), [](const auto& a, const auto& b) { return a.angle < b.angle; });

  const double startBlend = rotation.startZetaBlending, endBlend = rotation.endZetaBlending;
  lengthShare(startBlend, rotation.xpath + "/startZetaBlending");
  lengthShare(endBlend, rotation.xpath + "/endZetaBlending");
  // The inner curve's ends, each with the blending zeta it meets (the nearer one).
  gp_Pnt atStartBlend = inner->StartPoint(), atEndBlend = inner->EndPoint();
  const gp_Pnt outerStart = sections.front().at(startBlend);
  if (outerStart.Distance(atEndBlend) < outerStart.Distance(atStartBlend)) std::swap(atStartBlend, atEndBlend);
  // The inner curve in the plane at angle 0, revolved sector by sector.
  Handle(Geom_BSplineCurve) meridian = Handle(Geom_BSplineCurve)::DownCast(inner->Copy());
  for (int i = 1; i <= meridian->NbPoles(); ++i) {
    const Cylindrical c = cylindrical(meridian->Pole(i));
    meridian->SetPole(i, cartesian(c.x, c.r, 0.0));
  }
  const std::vector<double> front = zetasBetween(endBlend, 1.0), back = zetasBetween(-1.0, startBlend);

  // Each section sampled once: the stretch in front of the blending part (endZetaBlending over the
  // leading edge to the upper trailing edge), the one behind it (the lower trailing edge to
  // startZetaBlending) and, where blunt, the trailing edge's two ends.
  struct Sampled {
    Samples front, back, trailingEdge;
  };
  std::vector<Sampled> samples;
  for (const PlacedProfile& section : sections)
    samples.push_back({sampled(section, front), sampled(section, back), sampled(section, {1.0, -1.0})});
  const bool blunt = sections.front().at(1.0).Distance(sections.front().at(-1.0)) > Precision::Confusion();

  std::vector<std::pair<std::string, TopoDS_Face>> faces;
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const std::size_t next = (k + 1) % sections.size();
    const Sampled &a = samples[k], &b = samples[next];
    const double angleA = sections[k].angle,
                 angleB = k + 1 < sections.size() ? sections[next].angle : sections[next].angle + 360.0;
    const std::string name = cowl.uID + "/sector " + std::to_string(k + 1);
    faces.emplace_back(name, sectorFace(a.front, b.front, angleA, angleB));
    faces.emplace_back(name, sectorFace(a.back, b.back, angleA, angleB));
    if (blunt) faces.emplace_back(name, sectorFace(a.trailingEdge, b.trailingEdge, angleA, angleB));
    faces.emplace_back(name, blendingFace(a.back.back(), b.back.back(), angleA, angleB, atStartBlend));
    faces.emplace_back(name, blendingFace(a.front.front(), b.front.front(), angleA, angleB, atEndBlend));
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), angleA * kDegree);
    const TopoDS_Edge edge = TopoDS::Edge(BRepBuilderAPI_MakeEdge(meridian).Edge().Moved(turn));
    BRepPrimAPI_MakeRevol sweep(edge, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), (angleB - angleA) * kDegree);
    for (TopExp_Explorer face(sweep.Shape(), TopAbs_FACE); face.More(); face.Next())
      faces.emplace_back(name, TopoDS::Face(face.Current()));
  }
  try {
    return sewnNamedSolid(faces).shape;
  } catch (const Error& error) {
    throw Error(error.code(), "the cowl's sectors do not close into a solid: " + error.message(), {}, cowl.xpath);
  }
}

}  // namespace airshape::nacelle
