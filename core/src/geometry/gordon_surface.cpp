#include "airshape/geometry/gordon_surface.h"

#include <chrono>

#include "airshape/error.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/curve_network.h"
#include "airshape/geometry/reparametrisation.h"
#include "airshape/geometry/skinning.h"

namespace airshape::geometry {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

CurveFamily profileFamily(const CurveNetwork& network) {
  CurveFamily family{network.profiles, {}, network.profilesClosed};
  for (Eigen::Index k = 0; k < network.profileParameters.rows(); ++k) {
    const Eigen::VectorXd row = network.profileParameters.row(k).transpose();
    family.crossings.emplace_back(row.data(), row.data() + row.size());
  }
  return family;
}

CurveFamily guideFamily(const CurveNetwork& network) {
  CurveFamily family{network.guides, {}, network.guidesClosed};
  for (Eigen::Index l = 0; l < network.guideParameters.cols(); ++l) {
    const Eigen::VectorXd column = network.guideParameters.col(l);
    family.crossings.emplace_back(column.data(), column.data() + column.size());
  }
  return family;
}

/// Skinning parameters: the targets, plus the closing 1 for a periodic direction.
std::vector<double> sites(std::vector<double> targets, bool closed) {
  if (closed) targets.push_back(1.0);
  return targets;
}

}  // namespace

GordonSurface buildGordonSurface(const std::vector<Handle(Geom_BSplineCurve)>& profiles,
                                 const std::vector<Handle(Geom_BSplineCurve)>& guides,
                                 const GordonTolerances& tolerances, const KnownCrossings* known,
                                 int degreeAcrossProfiles) {
  GordonSurface result;
  auto start = Clock::now();
  const CurveNetwork network = buildCurveNetwork(profiles, guides, tolerances.crossing, known);
  for (Eigen::Index k = 0; k < network.profileParameters.rows(); ++k)
    for (Eigen::Index l = 0; l < network.profileParameters.cols(); ++l) {
      const gp_Pnt onProfile = network.profiles[static_cast<std::size_t>(k)]->Value(network.profileParameters(k, l));
      const gp_Pnt onGuide = network.guides[static_cast<std::size_t>(l)]->Value(network.guideParameters(k, l));
      result.crossings.emplace_back(0.5 * (onProfile.XYZ() + onGuide.XYZ()));
      result.maxCrossingGap = std::max(result.maxCrossingGap, onProfile.Distance(onGuide));
    }
  result.timings.intersection = secondsSince(start);

  start = Clock::now();
  const ReparametrisedFamily f = reparametrise(profileFamily(network), tolerances.approximation);
  const ReparametrisedFamily g = reparametrise(guideFamily(network), tolerances.approximation);
  result.timings.reparametrisation = secondsSince(start);

  start = Clock::now();
  const std::vector<double> uSites = sites(f.targets, network.profilesClosed);  // where the guides run
  const std::vector<double> vSites = sites(g.targets, network.guidesClosed);    // where the profiles run
  const KnotVector uSpace = skinningSpace(uSites, 3, network.profilesClosed);
  const KnotVector vSpace = skinningSpace(vSites, degreeAcrossProfiles, network.guidesClosed);
  Handle(Geom_BSplineSurface) skinnedProfiles = skinCurves(f.curves, vSites, vSpace);
  Handle(Geom_BSplineSurface) skinnedGuides = swapDirections(*skinCurves(g.curves, uSites, uSpace));
  std::vector<std::vector<gp_Pnt>> crossings(f.curves.size());
  for (std::size_t k = 0; k < f.curves.size(); ++k)
    for (std::size_t l = 0; l < g.curves.size(); ++l) {
      const gp_Pnt onProfile = f.curves[k]->Value(f.targets[l]);
      const gp_Pnt onGuide = g.curves[l]->Value(g.targets[k]);
      crossings[k].push_back(gp_Pnt(0.5 * (onProfile.XYZ() + onGuide.XYZ())));
    }
  Handle(Geom_BSplineSurface) tensor = interpolateGrid(crossings, uSites, uSpace, vSites, vSpace);
  result.timings.skinning = secondsSince(start);

  start = Clock::now();
  std::vector<Handle(Geom_BSplineSurface)> parts = {skinnedProfiles, skinnedGuides, tensor};
  makeCompatible(parts);
  Handle(Geom_BSplineSurface) gordon = Handle(Geom_BSplineSurface)::DownCast(parts[0]->Copy());
  for (int i = 1; i <= gordon->NbUPoles(); ++i)
    for (int j = 1; j <= gordon->NbVPoles(); ++j)
      gordon->SetPole(i, j,
                      gp_Pnt(parts[0]->Pole(i, j).XYZ() + parts[1]->Pole(i, j).XYZ() - parts[2]->Pole(i, j).XYZ()));
  result.surface = gordon;
  result.profileSites = g.targets;
  result.guideSites = f.targets;
  result.timings.combination = secondsSince(start);
  return result;
}

}  // namespace airshape::geometry
