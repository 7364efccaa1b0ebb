#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>

#include "airshape/geometry/curve_network.h"

namespace airshape::geometry {

/// Seconds spent in each stage of building a Gordon surface.
struct GordonTimings {
  double intersection = 0.0;
  double reparametrisation = 0.0;
  double skinning = 0.0;
  double combination = 0.0;
};

/// How closely the network must fit together and the surface follow it (model units).
struct GordonTolerances {
  double crossing = 1e-3;       ///< largest gap where a profile and a guide cross
  double approximation = 1e-5;  ///< largest deviation of a reparametrised curve from its input
};

struct GordonSurface {
  Handle(Geom_BSplineSurface) surface;
  GordonTimings timings;
  /// Where each profile crosses each guide: the midpoint of the two curves' closest points.
  std::vector<gp_Pnt> crossings;
  /// The largest distance between a profile and a guide where they cross (the input's own gap).
  double maxCrossingGap = 0.0;
  /// Where the profiles run (v, in the order of the network: along the guides) and where
  /// the guides run (u, along the profiles; the seam guide of a closed network once).
  std::vector<double> profileSites, guideSites;
};

/// The Gordon surface interpolating a curve network: S = S_f + S_g − T, where S_f skins the
/// (reparametrised) profiles, S_g skins the guides and T interpolates their crossing points,
/// all made compatible and combined into one B-spline surface (u along the profiles, v
/// along the guides). Closed profiles or guides give a periodic direction, smooth across
/// its seam. `known` crossings (see buildCurveNetwork) spare the search for them.
/// `degreeAcrossProfiles` is the degree of S_f and T across the profiles: 3 makes the
/// surface C2 everywhere; 1 blends linearly between neighbouring profiles (C0 at the
/// profiles, like the Coons patches of the reference library's guided lofts) while the
/// guides still shape it in between. Throws Error for a network that cannot be interpolated.
GordonSurface buildGordonSurface(const std::vector<Handle(Geom_BSplineCurve)>& profiles,
                                 const std::vector<Handle(Geom_BSplineCurve)>& guides,
                                 const GordonTolerances& tolerances, const KnownCrossings* known = nullptr,
                                 int degreeAcrossProfiles = 3);

}  // namespace airshape::geometry
