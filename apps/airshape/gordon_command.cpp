#include <chrono>
#include <iostream>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Bnd_Box.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Face.hxx>
#include <nlohmann/json.hpp>

#include "airshape/error.h"
#include "airshape/geometry/brep_curves.h"
#include "airshape/geometry/gordon_surface.h"
#include "airshape/geometry/surface_projection.h"
#include "commands.h"

namespace airshape::cli {

namespace {

using Curves = std::vector<Handle(Geom_BSplineCurve)>;

constexpr int kSamplesPerCurve = 200;
/// Relative to the network's size: the largest gap where two curves still cross, and how
/// closely the reparametrised curves follow the input (a tenth of the 1e-4 promised).
constexpr double kRelativeCrossingTolerance = 1e-3;
constexpr double kRelativeApproximationTolerance = 1e-5;

double boxDiagonal(const Curves& profiles, const Curves& guides) {
  Bnd_Box box;
  for (const Curves* family : {&profiles, &guides})
    for (const auto& curve : *family)
      for (int i = 0; i <= kSamplesPerCurve; ++i)
        box.Add(curve->Value(curve->FirstParameter() +
                             (curve->LastParameter() - curve->FirstParameter()) * i / kSamplesPerCurve));
  return std::sqrt(box.SquareExtent());
}

/// Distances from points to a surface. A fast projector (grid + Newton) gives an upper
/// bound; where that exceeds `exactAbove`, OCCT's global projection decides, so that a
/// point near a tight fold is never measured against the wrong side of it.
class DistanceToSurface {
 public:
  DistanceToSurface(const Handle(Geom_BSplineSurface) & surface, double exactAbove)
      : fast_(surface), exactAbove_(exactAbove) {
    double u1 = 0, u2 = 0, v1 = 0, v2 = 0;
    surface->Bounds(u1, u2, v1, v2);
    exact_.Init(surface, u1, u2, v1, v2);
  }

  double operator()(const gp_Pnt& point) {
    double distance = fast_.distance(point);
    if (distance > exactAbove_) {
      exact_.Perform(point);
      if (exact_.NbPoints() > 0) distance = std::min(distance, exact_.LowerDistance());
    }
    return distance;
  }

  /// The largest distance of sample points of the curves.
  double maxOver(const Curves& curves) {
    double worst = 0.0;
    for (const auto& curve : curves)
      for (int i = 0; i <= kSamplesPerCurve; ++i)
        worst = std::max(
            worst, (*this)(curve->Value(curve->FirstParameter() +
                                        (curve->LastParameter() - curve->FirstParameter()) * i / kSamplesPerCurve)));
    return worst;
  }

 private:
  geometry::SurfaceProjector fast_;
  GeomAPI_ProjectPointOnSurf exact_;
  double exactAbove_;
};

}  // namespace

int runGordon(const Arguments& arguments, plugin::PluginHost&) {
  std::string profilesPath, guidesPath, output;
  bool accuracy = false;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    if ((arguments[i] == "-o" || arguments[i] == "--output") && i + 1 < arguments.size()) {
      output = arguments[++i];
    } else if (arguments[i] == "--report") {
      accuracy = true;
    } else if (profilesPath.empty()) {
      profilesPath = arguments[i];
    } else if (guidesPath.empty()) {
      guidesPath = arguments[i];
    } else {
      throw Error(ErrorCode::InvalidArgument, "gordon: unexpected argument '" + arguments[i] + "'");
    }
  }
  if (profilesPath.empty() || guidesPath.empty() || output.empty())
    throw Error(ErrorCode::InvalidArgument,
                "usage: airshape gordon PROFILES.brep GUIDES.brep -o SURFACE.brep [--report]");

  const Curves profiles = geometry::readBrepCurves(profilesPath);
  const Curves guides = geometry::readBrepCurves(guidesPath);
  const double diagonal = boxDiagonal(profiles, guides);
  if (!(diagonal > 0.0)) throw Error(ErrorCode::InvalidArgument, "the curve network has no extent", profilesPath);

  const auto start = std::chrono::steady_clock::now();
  geometry::GordonSurface gordon;
  try {
    gordon = geometry::buildGordonSurface(
        profiles, guides, {kRelativeCrossingTolerance * diagonal, kRelativeApproximationTolerance * diagonal});
  } catch (const Error& error) {
    throw error.inFile(profilesPath + " + " + guidesPath);
  } catch (const Standard_Failure& failure) {  // a network OCCT cannot work with, named by its files
    throw Error(ErrorCode::InvalidArgument,
                std::string("the curve network cannot be interpolated (geometry kernel failure: ") +
                    failure.GetMessageString() + ")",
                profilesPath + " + " + guidesPath);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  geometry::writeBrep(BRepBuilderAPI_MakeFace(gordon.surface, 1e-7).Face(), output);

  const auto& surface = gordon.surface;
  nlohmann::json report = {{"degree_u", surface->UDegree()},
                           {"degree_v", surface->VDegree()},
                           {"poles_u", surface->NbUPoles()},
                           {"poles_v", surface->NbVPoles()},
                           {"periodic_u", surface->IsUPeriodic()},
                           {"periodic_v", surface->IsVPeriodic()},
                           {"seconds", seconds},
                           {"bbox_diagonal", diagonal},
                           {"max_crossing_gap", gordon.maxCrossingGap},
                           {"timings",
                            {{"intersection", gordon.timings.intersection},
                             {"reparametrisation", gordon.timings.reparametrisation},
                             {"skinning", gordon.timings.skinning},
                             {"combination", gordon.timings.combination}}}};
  if (accuracy) {
    // Sampling every input curve against the surface costs several times the surface itself.
    DistanceToSurface distance(surface, 1e-5 * diagonal);
    double crossingDistance = 0.0;
    for (const gp_Pnt& crossing : gordon.crossings) crossingDistance = std::max(crossingDistance, distance(crossing));
    report["max_profile_distance"] = distance.maxOver(profiles);
    report["max_guide_distance"] = distance.maxOver(guides);
    report["max_intersection_distance"] = crossingDistance;
  }
  std::cout << report.dump() << '\n';
  return kSuccess;
}

}  // namespace airshape::cli
