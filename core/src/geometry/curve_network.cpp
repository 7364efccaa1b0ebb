#include "airshape/geometry/curve_network.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>

#include <gp_Vec.hxx>

#include "airshape/error.h"
#include "airshape/geometry/periodic_curve.h"
#include "airshape/parallel_for.h"

namespace airshape::geometry {

namespace {

/// Where two curves come closest: parameters and distance.
struct CurveCrossing {
  double first;
  double second;
  double distance;
};

constexpr int kSamples = 64;

double clampTo(const Geom_BSplineCurve& curve, double t) {
  if (curve.IsPeriodic()) return t;
  return std::clamp(t, curve.FirstParameter(), curve.LastParameter());
}

/// Newton's method on the squared distance |a(s) - b(t)|².
CurveCrossing refine(const Geom_BSplineCurve& a, const Geom_BSplineCurve& b, double s, double t) {
  for (int iteration = 0; iteration < 50; ++iteration) {
    gp_Pnt pa, pb;
    gp_Vec da, db, dda, ddb;
    a.D2(s, pa, da, dda);
    b.D2(t, pb, db, ddb);
    const gp_Vec r(pb, pa);
    const double g1 = r.Dot(da), g2 = -r.Dot(db);
    const double h11 = da.Dot(da) + r.Dot(dda), h22 = db.Dot(db) - r.Dot(ddb), h12 = -da.Dot(db);
    const double det = h11 * h22 - h12 * h12;
    if (std::abs(det) < 1e-300) break;
    const double ds = -(h22 * g1 - h12 * g2) / det, dt = -(h11 * g2 - h12 * g1) / det;
    const double sNew = clampTo(a, s + ds), tNew = clampTo(b, t + dt);
    const bool converged = std::abs(sNew - s) < 1e-14 && std::abs(tNew - t) < 1e-14;
    s = sNew;
    t = tNew;
    if (converged) break;
  }
  return {s, t, a.Value(s).Distance(b.Value(t))};
}

std::vector<double> samples(const Geom_BSplineCurve& curve) {
  std::vector<double> t(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i)
    t[static_cast<std::size_t>(i)] =
        curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / kSamples;
  return t;
}

bool isClosed(const Geom_BSplineCurve& curve, double tolerance) {
  return curve.IsPeriodic() || curve.StartPoint().Distance(curve.EndPoint()) <= tolerance;
}

/// Closed with the same tangent direction on both sides of the seam (within about 1°).
bool isSmoothlyClosed(const Geom_BSplineCurve& curve, double tolerance) {
  if (curve.IsPeriodic()) return true;
  if (!isClosed(curve, tolerance)) return false;
  const gp_Vec start = curve.DN(curve.FirstParameter(), 1), end = curve.DN(curve.LastParameter(), 1);
  return start.Magnitude() > 0 && end.Magnitude() > 0 && start.Angle(end) < 0.0175;
}

/// Whether the point at t is the seam point of a closed curve (within the crossing tolerance).
bool atSeam(const Geom_BSplineCurve& curve, double t, double tolerance) {
  return curve.Value(t).Distance(curve.StartPoint()) <= tolerance;
}

/// One family of the network (profiles or guides) with its crossing parameters:
/// own(c, j) lies on curve c, at crossing curve j of the other family.
struct Family {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  Eigen::MatrixXd own;
  bool periodic = false;
  bool closedWithCorner = false;
  double tolerance = 0.0;
};

/// Reverses a curve (keeping its parameter range) and maps its crossing parameters along.
void reverseCurve(Family& family, Eigen::Index c) {
  Handle(Geom_BSplineCurve)& curve = family.curves[static_cast<std::size_t>(c)];
  curve->Reverse();
  for (Eigen::Index j = 0; j < family.own.cols(); ++j) family.own(c, j) = curve->ReversedParameter(family.own(c, j));
}

/// For periodic curves a crossing at the end of the period is the one at its start.
void wrapSeams(Family& family) {
  for (Eigen::Index c = 0; c < family.own.rows(); ++c) {
    const Geom_BSplineCurve& curve = *family.curves[static_cast<std::size_t>(c)];
    const double last = curve.LastParameter(), span = last - curve.FirstParameter();
    for (Eigen::Index j = 0; j < family.own.cols(); ++j)
      if (family.own(c, j) > last - 1e-9 * span) family.own(c, j) = curve.FirstParameter();
  }
}

/// Periodic copies of smoothly closed curves, so that the seam is no special place.
void makePeriodic(Family& family) {
  for (Eigen::Index c = 0; c < family.own.rows(); ++c) {
    Handle(Geom_BSplineCurve)& curve = family.curves[static_cast<std::size_t>(c)];
    if (curve->IsPeriodic()) continue;
    std::vector<double> parameters(family.own.row(c).data(), family.own.row(c).data() + 0);
    for (Eigen::Index j = 0; j < family.own.cols(); ++j) parameters.push_back(family.own(c, j));
    curve = periodicCopy(*curve, parameters);
    for (Eigen::Index j = 0; j < family.own.cols(); ++j) family.own(c, j) = parameters[static_cast<std::size_t>(j)];
  }
  wrapSeams(family);
}

/// Crossing curves that meet every curve of the family where an earlier one does: repeats.
std::vector<Eigen::Index> repeatedCrossers(const Family& family, double tolerance) {
  std::vector<Eigen::Index> repeats;
  for (Eigen::Index j = 1; j < family.own.cols(); ++j)
    for (Eigen::Index i = 0; i < j; ++i) {
      bool same = true;
      for (Eigen::Index c = 0; c < family.own.rows() && same; ++c) {
        const auto& curve = *family.curves[static_cast<std::size_t>(c)];
        same = curve.Value(family.own(c, i)).Distance(curve.Value(family.own(c, j))) <= tolerance;
      }
      if (same) {
        repeats.push_back(j);
        break;
      }
    }
  return repeats;
}

void dropColumn(Eigen::MatrixXd& m, Eigen::Index j) {
  Eigen::MatrixXd kept(m.rows(), m.cols() - 1);
  kept << m.leftCols(j), m.rightCols(m.cols() - j - 1);
  m = kept;
}

void dropRow(Eigen::MatrixXd& m, Eigen::Index j) {
  Eigen::MatrixXd kept(m.rows() - 1, m.cols());
  kept << m.topRows(j), m.bottomRows(m.rows() - j - 1);
  m = kept;
}

/// Which way a curve runs through its crossings, against the reference order: +1, -1,
/// 0 when it meets them in another order, 2 when too few crossings tell. Seam crossings of curves with a corner at the
/// seam are left out (they sit at both ends).
int direction(const Family& family, Eigen::Index c, const std::vector<Eigen::Index>& reference) {
  std::vector<double> values;
  for (Eigen::Index j : reference) {
    const double t = family.own(c, j);
    if (family.closedWithCorner && atSeam(*family.curves[static_cast<std::size_t>(c)], t, family.tolerance)) continue;
    values.push_back(t);
  }
  if (values.size() < 2) return 2;  // too few crossings away from the seam to tell
  int rising = 0, falling = 0;
  for (std::size_t i = 1; i < values.size(); ++i) (values[i] > values[i - 1] ? rising : falling)++;
  if (family.periodic && values.size() > 1) (values.front() > values.back() ? rising : falling)++;
  const int allowed = family.periodic ? 1 : 0;
  if (falling <= allowed) return 1;
  if (rising <= allowed) return -1;
  return 0;
}

/// Whether curve c runs against the (already oriented) curve r: compares the points at a
/// quarter and three quarters of both. For curves whose crossings cannot tell, such as
/// sharp-edged airfoils crossed only at the trailing and leading edge.
bool runsAgainst(const Geom_BSplineCurve& c, const Geom_BSplineCurve& r) {
  auto at = [](const Geom_BSplineCurve& curve, double share) {
    return curve.Value(curve.FirstParameter() + share * (curve.LastParameter() - curve.FirstParameter()));
  };
  const gp_Pnt a = at(c, 0.25), b = at(c, 0.75), ra = at(r, 0.25), rb = at(r, 0.75);
  return a.Distance(rb) + b.Distance(ra) < a.Distance(ra) + b.Distance(rb);
}

/// Seam crossings of curves closed with a corner: the first crossing curve in file order
/// that meets the seam takes the start, a second one the end.
void assignSeamEnds(Family& family) {
  if (!family.closedWithCorner) return;
  for (Eigen::Index c = 0; c < family.own.rows(); ++c) {
    const auto& curve = *family.curves[static_cast<std::size_t>(c)];
    bool startTaken = false;
    for (Eigen::Index j = 0; j < family.own.cols(); ++j) {
      if (!atSeam(curve, family.own(c, j), family.tolerance)) continue;
      family.own(c, j) = startTaken ? curve.LastParameter() : curve.FirstParameter();
      startTaken = true;
    }
  }
}

std::vector<Eigen::Index> orderOf(const Eigen::VectorXd& values) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(values.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return values(a) < values(b); });
  return order;
}

/// A curve's points at its sample parameters: where searches for closest approaches start.
struct SampledCurve {
  std::vector<double> parameters;
  std::vector<gp_Pnt> points;
};

SampledCurve sampled(const Geom_BSplineCurve& curve) {
  SampledCurve result{samples(curve), {}};
  for (double t : result.parameters) result.points.push_back(curve.Value(t));
  return result;
}

/// The closest approach from the curves' samples (each curve sampled once for all the curves
/// it crosses): the few best sample pairs are refined; the best refinement wins.
CurveCrossing closestApproach(const Geom_BSplineCurve& a, const SampledCurve& sa, const Geom_BSplineCurve& b,
                              const SampledCurve& sb) {
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> candidates;
  candidates.reserve(sa.points.size() * sb.points.size());
  for (std::size_t i = 0; i < sa.points.size(); ++i)
    for (std::size_t j = 0; j < sb.points.size(); ++j)
      candidates.push_back({sa.points[i].SquareDistance(sb.points[j]), {i, j}});
  const std::size_t keep = std::min<std::size_t>(4, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + static_cast<long>(keep), candidates.end());
  CurveCrossing best{0, 0, HUGE_VAL};
  for (std::size_t c = 0; c < keep; ++c) {
    const CurveCrossing crossing =
        refine(a, b, sa.parameters[candidates[c].second.first], sb.parameters[candidates[c].second.second]);
    if (crossing.distance < best.distance) best = crossing;
  }
  return best;
}

}  // namespace

CurveNetwork buildCurveNetwork(std::vector<Handle(Geom_BSplineCurve)> profiles,
                               std::vector<Handle(Geom_BSplineCurve)> guides, double tolerance,
                               const KnownCrossings* known) {
  if (profiles.size() < 2 || guides.size() < 2)
    throw Error(ErrorCode::InvalidArgument, "a curve network needs at least two profiles and two guides (got " +
                                                std::to_string(profiles.size()) + " and " +
                                                std::to_string(guides.size()) + ")");
  const auto K = static_cast<Eigen::Index>(profiles.size()), L = static_cast<Eigen::Index>(guides.size());
  CurveNetwork network;
  network.profileParameters.resize(K, L);
  network.guideParameters.resize(K, L);
  // Every pair of a profile and a guide on every core, each curve sampled once.
  std::vector<SampledCurve> profileSamples(profiles.size()), guideSamples(guides.size());
  if (!known) {
    parallelFor(profiles.size() + guides.size(), [&](std::size_t i) {
      if (i < profiles.size())
        profileSamples[i] = sampled(*profiles[i]);
      else
        guideSamples[i - profiles.size()] = sampled(*guides[i - profiles.size()]);
    });
  }
  parallelFor(static_cast<std::size_t>(K * L), [&](std::size_t pair) {
    const auto k = static_cast<Eigen::Index>(pair) / L, l = static_cast<Eigen::Index>(pair) % L;
    const Geom_BSplineCurve& profile = *profiles[static_cast<std::size_t>(k)];
    const Geom_BSplineCurve& guide = *guides[static_cast<std::size_t>(l)];
    const CurveCrossing crossing = known ? CurveCrossing{known->profileParameters(k, l), known->guideParameters(k, l),
                                                         profile.Value(known->profileParameters(k, l))
                                                             .Distance(guide.Value(known->guideParameters(k, l)))}
                                         : closestApproach(profile, profileSamples[static_cast<std::size_t>(k)], guide,
                                                           guideSamples[static_cast<std::size_t>(l)]);
    if (crossing.distance > tolerance) {
      throw Error(ErrorCode::InvalidArgument, "guide " + std::to_string(l + 1) + " misses profile " +
                                                  std::to_string(k + 1) + " by " + std::to_string(crossing.distance) +
                                                  " (tolerance " + std::to_string(tolerance) + ")");
    }
    network.profileParameters(k, l) = crossing.first;
    network.guideParameters(k, l) = crossing.second;
  });

  // A crossing counts as at the seam of a curve closed with a corner when it lies much closer
  // to the seam point than crossing curves lie to each other.
  const double seamTolerance = 0.01 * tolerance;
  Family profileFamily{profiles, network.profileParameters, false, false, seamTolerance};
  Family guideFamily{guides, network.guideParameters.transpose(), false, false, seamTolerance};
  for (Family* family : {&profileFamily, &guideFamily}) {
    const bool closed = std::all_of(family->curves.begin(), family->curves.end(),
                                    [&](const auto& c) { return isClosed(*c, tolerance); });
    family->periodic = closed && std::all_of(family->curves.begin(), family->curves.end(),
                                             [&](const auto& c) { return isSmoothlyClosed(*c, tolerance); });
    family->closedWithCorner = closed && !family->periodic;
    if (family->periodic) makePeriodic(*family);
  }
  // A closed network often repeats its seam curve at the end; the repeat adds nothing.
  for (auto [family, crossers] : {std::pair{&profileFamily, &guideFamily}, std::pair{&guideFamily, &profileFamily}}) {
    if (!family->periodic) continue;
    const std::vector<Eigen::Index> repeats = repeatedCrossers(*family, tolerance);
    for (auto it = repeats.rbegin(); it != repeats.rend(); ++it) {
      crossers->curves.erase(crossers->curves.begin() + *it);
      dropColumn(family->own, *it);
      dropRow(crossers->own, *it);
    }
  }
  if (profileFamily.curves.size() < 2 || guideFamily.curves.size() < 2)
    throw Error(ErrorCode::InvalidArgument, "the network has fewer than two distinct profiles or guides");

  // Orientation: every curve must meet the crossing curves in the order the first one does.
  for (auto [family, crossers, name] :
       {std::tuple{&profileFamily, &guideFamily, "profile"}, std::tuple{&guideFamily, &profileFamily, "guide"}}) {
    const std::vector<Eigen::Index> reference = orderOf(family->own.row(0).transpose());
    const std::vector<Eigen::Index> alongCrosser = orderOf(crossers->own.row(0).transpose());
    for (std::size_t position = 0; position < alongCrosser.size(); ++position) {
      const Eigen::Index c = alongCrosser[position];
      int sense = direction(*family, c, reference);
      if (sense == 2) {  // decided by the neighbour along the first crossing curve
        const bool against =
            position > 0 && runsAgainst(*family->curves[static_cast<std::size_t>(c)],
                                        *family->curves[static_cast<std::size_t>(alongCrosser[position - 1])]);
        sense = against ? -1 : 1;
      }
      const std::string others = family == &profileFamily ? "guides" : "profiles";
      // The first curve sets the order; where even it runs against it, two crossings tie.
      if (sense == 0 && c == 0)
        throw Error(ErrorCode::InvalidArgument, "two " + others + " meet " + name + " 1 at one point");
      if (sense == 0)
        throw Error(ErrorCode::InvalidArgument, std::string(name) + " " + std::to_string(c + 1) + " meets the " +
                                                    others + " in another order than " + name + " 1");
      if (sense < 0) reverseCurve(*family, c);
    }
    assignSeamEnds(*family);
  }

  // Order: guides along profile 1, profiles along guide 1.
  const std::vector<Eigen::Index> guidesSorted = orderOf(profileFamily.own.row(0).transpose());
  const std::vector<Eigen::Index> profilesSorted = orderOf(guideFamily.own.row(0).transpose());
  CurveNetwork sorted;
  sorted.profilesClosed = profileFamily.periodic;
  sorted.guidesClosed = guideFamily.periodic;
  const auto count = [](const std::vector<Eigen::Index>& v) { return static_cast<Eigen::Index>(v.size()); };
  sorted.profileParameters.resize(count(profilesSorted), count(guidesSorted));
  sorted.guideParameters.resize(count(profilesSorted), count(guidesSorted));
  for (Eigen::Index k = 0; k < count(profilesSorted); ++k) {
    const Eigen::Index p = profilesSorted[static_cast<std::size_t>(k)];
    sorted.profiles.push_back(profileFamily.curves[static_cast<std::size_t>(p)]);
    for (Eigen::Index l = 0; l < count(guidesSorted); ++l) {
      const Eigen::Index g = guidesSorted[static_cast<std::size_t>(l)];
      sorted.profileParameters(k, l) = profileFamily.own(p, g);
      sorted.guideParameters(k, l) = guideFamily.own(g, p);
    }
  }
  for (Eigen::Index g : guidesSorted) sorted.guides.push_back(guideFamily.curves[static_cast<std::size_t>(g)]);
  return sorted;
}

}  // namespace airshape::geometry
